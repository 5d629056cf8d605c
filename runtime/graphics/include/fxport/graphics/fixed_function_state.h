// FixedFunctionState: the D3D9 render states that D3D9-era effects and shaders rely on and that
// XNA 4 has no API for (XNA's HiDef profile dropped fixed-function fog, points and clip planes, and
// keeps alpha test only inside AlphaTestEffect). An effect pass's D3D9 states (`FogEnable = true;`,
// `PointSize = 8;`, `ClipPlaneEnable = 3;`, `AlphaTestEnable = true;`, `ShadeMode = Flat;` ...) set
// GraphicsDevice::FixedFunction at Apply(); a program drawing loose shaders, or one that wants to
// change them after Apply(), assigns the member itself, as with BlendState. GL 4.5 core has none of
// these stages: the device emulates them in variants of the shaders (xlate/fixed_function.h).
#pragma once

#include <array>
#include <cstdint>

#include "fxport/graphics/depth_stencil_state.h"
#include "fxport/math.h"

namespace fxport {

// D3DFOGMODE.
enum class FogMode : std::uint8_t { None, Exponential, ExponentialSquared, Linear };
// D3DSHADEMODE (Phong was never implemented by D3D9 drivers; it shades as Gouraud).
enum class ShadeMode : std::uint8_t { Flat, Gouraud };

struct FixedFunctionState {
    // Fog (D3DRS_FOG*), blended into render target 0's colour after the pixel shader:
    //   colour.rgb = lerp(FogColor.rgb, colour.rgb, saturate(f)); alpha is left alone.
    // FogTableMode None is "vertex fog": f is what the vertex shader writes to FOG (else COLOR1's w,
    // as D3D9 hardware keeps the fog factor in the specular alpha). Exponential, ExponentialSquared,
    // Linear compute f per pixel from the depth d:
    //   exp(-FogDensity d), exp(-(FogDensity d)^2), (FogEnd - d) / (FogEnd - FogStart)
    // (FogStart == FogEnd fogs everything, as D3D9 does). d is the pixel's z in [0, 1], or its eye
    // depth w when FogFromW is set: D3D9 takes w when the projection matrix is not orthographic,
    // which shaders never tell it, so the program says which.
    bool FogEnable = false;
    FogMode FogTableMode = FogMode::None;
    // D3D9 ignores the vertex fog mode whenever a vertex shader runs (fxport always has one): kept
    // so that a pass's FogVertexMode reads back, never used.
    FogMode FogVertexMode = FogMode::None;
    Vector4 FogColor = Vector4(0, 0, 0, 0);
    float FogStart = 0, FogEnd = 1, FogDensity = 1;
    bool FogFromW = false;

    // Points (D3DRS_POINTSIZE, _MIN, _MAX, POINTSPRITEENABLE). A point is PointSize pixels wide,
    // or what the vertex shader writes to PSIZE, clamped to [PointSizeMin, PointSizeMax]. With
    // point sprites on, every TEXCOORDn the pixel shader reads runs from (0, 0) at the point's
    // top-left corner to (1, 1) at its bottom-right.
    float PointSize = 1, PointSizeMin = 1, PointSizeMax = 64;
    bool PointSpriteEnable = false;

    // User clip planes (D3DRS_CLIPPLANEENABLE bits 0..5, SetClipPlane): a vertex is kept where
    // dot(position, ClipPlanes[i]) >= 0 for each enabled i, in clip space (the position the vertex
    // shader writes), as D3D9 does for programmable vertex processing.
    std::uint32_t ClipPlaneEnable = 0;
    std::array<Vector4, 6> ClipPlanes{};

    // Alpha test (D3DRS_ALPHATESTENABLE / ALPHAFUNC / ALPHAREF): the pixel is kept when
    // `alpha AlphaFunction ReferenceAlpha / 255` holds, alpha being the shader's (unclamped) output.
    // ReferenceAlpha is D3D9's 8-bit value (only its low 8 bits count).
    bool AlphaTestEnable = false;
    CompareFunction AlphaFunction = CompareFunction::Always;
    int ReferenceAlpha = 0;

    // D3DRS_SHADEMODE: Flat gives COLORn inputs of the pixel shader the first vertex's value.
    fxport::ShadeMode ShadeMode = fxport::ShadeMode::Gouraud;

    bool operator==(const FixedFunctionState&) const = default;
};

}  // namespace fxport
