// Step 3b: a generated entry point around the effect's own VS/PS function.
//
// glslang maps DX9 semantics only on plain entry parameters, never on struct members, and it gives
// varyings locations in declaration order. Instead of editing the user's structs, we append
//
//     fxport_VSOutput fxport_main(float4 i0 : POSITION0, ...) { VSI a0; a0.Position = i0; ...
//                                                              VSO r = VS(a0, true, 3); ... }
//
// whose flat parameters and outputs carry exactly the semantics we want: POSITION -> SV_Position,
// COLORn -> SV_Targetn, VPOS/VFACE from the fragment built-ins, every varying widened to float4 so
// any VS/PS pair with matching semantics links (DX9 lets a PS read float2 of a float4 output), the
// literal arguments of `compile ps_2_0 PS(true, 3)` passed to `uniform` parameters. A vs_1_1..vs_3_0
// shader is marked as drawing with D3D9's pixel centres, which the device applies through the
// viewport's origin (GraphicsDevice::Impl::applyViewport), not the shader.
#pragma once

#include <string>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

inline constexpr const char* kWrapperEntry = "fxport_main";
// A pixel shader's SV_Coverage input: glslang drops that built-in input (its reads become OpUndef),
// so the wrapper reads it as a flat uint varying on this semantic, and spirv_to_glsl turns the
// varying into GL's gl_SampleMaskIn[0].
inline constexpr const char* kSampleMaskInSemantic = "FXPORT_SAMPLEMASKIN";

struct EntryWrapper {
    std::string code;        // HLSL to append after the effect
    std::string error;       // non-empty: why the entry cannot be wrapped (FX1403)
    bool usesPixelOffset = false;  // an SM1-3 vertex shader: D3D9 pixel centres (CompiledShader::needsD3D9PixelOffset)
};

// `nextToGeometryShader`: the VS feeds, or the PS is fed by, a geometry shader. D3D10 matches those
// signatures exactly, and so must GL: varyings keep their declared types, and a VS's POSITION stays
// an ordinary varying (the GS writes SV_Position).
EntryWrapper buildEntryWrapper(const EffectSyntax& syntax, const FxFunction& entry, const ShaderProfile& profile,
                               const std::string& arguments, bool nextToGeometryShader = false);

// Splits "TEXCOORD12" into ("TEXCOORD", 12), upper-cased; "SV_Target" -> ("SV_TARGET", 0).
std::pair<std::string, int> splitSemantic(const std::string& semantic);

}  // namespace fxport::xlate
