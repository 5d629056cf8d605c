// INTERNAL, GL-free: a compiled shader as the device draws with it (a separable program and the
// caches made from it), shared by the device and the effects that own the programs.
#pragma once

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>

#include "device/backend.h"
#include "fxport/xlate/texture_fetches.h"

namespace fxport::xlate {
struct CompiledShader;
}

namespace fxport {

struct ComputeAnalysis;  // gl/passes/compute_pass.h

// A shader's variant with D3D9 fixed-function stages added; program 0: the shader cannot have them
// (said once, when it was asked for).
struct FixedFunctionVariant {
    BackendObject program = 0;
    std::array<int, 8> locations{-1, -1, -1, -1, -1, -1, -1, -1};  // by FixedFunctionUniform
};

// A compiled shader made into a separable program (a backend object), as the device needs it at draw time.
struct ShaderProgram {
    BackendObject program = 0;
    int stage = 0;                              // 0 vertex, 1 pixel, 2 geometry, 3 hull, 4 domain, 5 compute
    const xlate::CompiledShader* shader = nullptr;  // owned by the effect
    std::string label;                          // "GBuffer.fx: VertexShaderFunction (vs_2_0)"
    bool mayDiscard = false;                    // the GLSL has a `discard` (clip, texkill): read once
    // Variants that emulate D3D9 fixed-function states (xlate/fixed_function.h, fixed_function_draw.cpp),
    // by what they emulate, made at the first draw that needs one; a cache on a record the device
    // otherwise only reads, hence mutable.
    mutable std::map<int, FixedFunctionVariant> fixedFunctionVariants;
    // What compute passes may do with this shader (compute_pass.h), read at its first candidate draw.
    mutable std::shared_ptr<const ComputeAnalysis> computeAnalysis;
    // Pixel shaders: texture fetches per fragment, counted at the first draw the tally sees.
    mutable std::optional<xlate::TextureFetches> textureFetches;
    // The units its sampler2DMS uniforms read (a bit each), asked of the backend at its first draw.
    mutable std::optional<unsigned> multisampledUnits;
};

}  // namespace fxport
