// Step 4a: HLSL -> SPIR-V. The only file that calls glslang's compiler, so that DXC or
// vkd3d-shader can replace it (glslang's HLSL front end is deprecated since April 2026).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fxport/xlate/compiled_effect.h"

namespace fxport::xlate {

struct HlslError {
    int line = 0;          // line in `source` (1-based), 0 if unknown
    std::string token;     // offending token, when the front end names one
    std::string message;
    bool aboutTheEntryPoint = false;  // the whole shader's (our checks on SPIR-V): said at the entry function
};

struct SpirvModule {
    std::vector<std::uint32_t> words;
    std::vector<HlslError> errors;  // non-empty = failed
    std::string warnings;
};

struct HlslToSpirvRequest {
    const std::string* source = nullptr;
    ShaderStage stage = ShaderStage::Vertex;
    std::string entryPoint;
    bool dx9Compatible = false;  // tex2D/sampler2D (DX9 samplers) vs Texture2D.Sample (DX10)
    int shaderModel = 4;         // the profile's major version: fxc's constant-folding errors differ
    // A hull shader's [partitioning] (pow2_partitioning.h, tess_factor_intrinsics.h); empty otherwise.
    std::string hullPartitioning;
    // A pixel shader's rasterizer-ordered views, declared as UAVs (rasterizer_ordered_views.h).
    std::vector<std::string> rasterizerOrderedViews;
};

SpirvModule hlslToSpirv(const HlslToSpirvRequest& request);

}  // namespace fxport::xlate
