// D3D9 fixed-function stages that GL 4.5 core lacks, as variants of a shader's GLSL (the pattern of
// alpha_test.h, which this generalises): the variant renames the shader's main() and wraps it.
//
// Pixel shaders (after the shader, on the colour of render target 0, as D3D9 does it):
//   - alpha test: discard unless  output0.a FUNC fxport_AlphaRef  (see alpha_test.h);
//   - fog: output0.rgb = mix(fxport_FogColor.rgb, output0.rgb, saturate(f)), alpha untouched, where
//     fxport_FogMode 0 (D3DFOG_NONE table mode: "vertex fog") takes f from the vertex shader's FOG
//     output (else COLOR1.w, else 0), and 1 EXP / 2 EXP2 / 3 LINEAR compute it per pixel from the
//     depth d = z (gl_FragCoord.z, 0..1) or, with fxport_FogParams.w != 0, the eye depth
//     w = 1 / gl_FragCoord.w:  EXP exp(-density d), EXP2 exp(-(density d)^2),
//     LINEAR (end - d) / (end - start); fxport_FogParams = (start, end, density, fromW);
//   - point sprites: every TEXCOORDn input (locations 0..15) reads (gl_PointCoord, 0, 1) instead;
//   - flat shading: COLORn inputs (locations 16..19) are `flat` (GL's provoking vertex is the first,
//     as D3D9's).
// Vertex shaders (the last stage before the rasteriser):
//   - user clip planes: gl_ClipDistance[i] = dot(position, fxport_ClipPlanes[i]) for i < count, with
//     the position the shader wrote (clip space, before fxport's D3D9 half-pixel offset);
//   - point size: gl_PointSize = clamp(PSIZE output .x, fxport_PointSize.y, fxport_PointSize.z)
//     (fxport_PointSize = (size, min, max)); a shader without PSIZE is drawn at the device's point
//     size, which the runtime clamps itself.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace fxport::xlate {

inline constexpr const char* kFogColorUniform = "fxport_FogColor";
inline constexpr const char* kFogModeUniform = "fxport_FogMode";
inline constexpr const char* kFogParamsUniform = "fxport_FogParams";
inline constexpr const char* kClipPlanesUniform = "fxport_ClipPlanes";
inline constexpr const char* kPointSizeUniform = "fxport_PointSize";
inline constexpr int kMaxUserClipPlanes = 6;  // D3D9's D3DMAXUSERCLIPPLANES is 32; drivers expose 6

// Where a pixel variant's vertex fog factor comes from.
struct FogInput {
    int location = -1;   // the writer's varying location (-1: none written, the factor is 0)
    int component = 0;   // 0: FOG's .x; 3: COLOR1's .w
};

struct PixelFixedFunction {
    bool alphaTest = false;
    bool fog = false;
    FogInput fogInput;
    bool pointSprite = false;
    bool flatColors = false;
    bool any() const { return alphaTest || fog || pointSprite || flatColors; }
};

struct VertexFixedFunction {
    int clipPlanes = 0;          // 0..kMaxUserClipPlanes
    int pointSizeLocation = -1;  // location of the shader's PSIZE output (-1: it writes none)
    bool any() const { return clipPlanes > 0 || pointSizeLocation >= 0; }
};

// Empty with `why` set when the GLSL does not have the shape the variant needs (no vec4 output 0
// for the alpha test or fog; a vertex shader that writes gl_ClipDistance itself).
std::optional<std::string> pixelFixedFunctionVariant(const std::string& glsl, const PixelFixedFunction& wanted, std::string& why);
std::optional<std::string> vertexFixedFunctionVariant(const std::string& glsl, const VertexFixedFunction& wanted, std::string& why);

}  // namespace fxport::xlate
