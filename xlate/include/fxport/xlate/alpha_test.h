// D3D9's alpha test (AlphaTestEnable / AlphaFunc / AlphaRef), which GL core lacks, as a pixel-shader
// variant: the shader's GLSL with a main() that runs the original and discards the pixel unless
//   output0.a FUNC fxport_AlphaRef
// where output0 is the colour written to render target 0 (unclamped, in float) and the runtime
// sets fxport_AlphaRef = (AlphaRef & 0xFF) / 255 and fxport_AlphaFunc to the D3DCMPFUNC code (1 NEVER,
// 2 LESS, 3 EQUAL, 4 LESSEQUAL, 5 GREATER, 6 NOTEQUAL, 7 GREATEREQUAL, 8 ALWAYS). This is the
// comparison Wine's d3d9 makes (checked there against Windows drivers by its visual tests).
#pragma once

#include <optional>
#include <string>

namespace fxport::xlate {

inline constexpr const char* kAlphaFuncUniform = "fxport_AlphaFunc";
inline constexpr const char* kAlphaRefUniform = "fxport_AlphaRef";

// Empty when the shader writes no vec4 colour to location 0 (nothing to test).
std::optional<std::string> alphaTestVariant(const std::string& pixelShaderGlsl);

}  // namespace fxport::xlate
