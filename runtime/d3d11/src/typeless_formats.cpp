// Typeless formats. The depth ones D3D programs make shadow maps of: a texture of R32_TYPELESS,
// R24G8_TYPELESS, R32G8X24_TYPELESS or R16_TYPELESS is written through a depth-stencil view
// (D32_FLOAT, D24_UNORM_S8_UINT, D32_FLOAT_S8X24_UINT, D16_UNORM) and read through a
// shader-resource view (R32_FLOAT, R24_UNORM_X8_TYPELESS, R32_FLOAT_X8X24_TYPELESS, R16_UNORM) --
// one depth texture underneath; the stencil of R24G8 / R32G8X24 is read through an
// X24_TYPELESS_G8_UINT / X32_TYPELESS_G8X24_UINT view (a GL texture view in stencil mode). And the colour ones whose members GL can view one as another (a
// texture view of the same bytes per texel or block): the texture is stored in its family's first
// format and a view in another (sRGB, signed, integer) reads it through a GL texture view -- a
// render-target view draws into one (core::TargetView), an unordered-access view writes through one.
#include "d3d11_impl.h"

namespace fxport::d3d11 {

namespace {

const DepthFamily kFamilies[] = {
    {DXGI_FORMAT_R32_TYPELESS, DXGI_FORMAT_D32_FLOAT, DXGI_FORMAT_R32_FLOAT, DepthFormat::Depth32F, SurfaceFormat::Depth32},
    {DXGI_FORMAT_R24G8_TYPELESS, DXGI_FORMAT_D24_UNORM_S8_UINT, DXGI_FORMAT_R24_UNORM_X8_TYPELESS, DepthFormat::Depth24Stencil8,
     SurfaceFormat::Depth24Stencil8, DXGI_FORMAT_X24_TYPELESS_G8_UINT, SurfaceFormat::StencilOfDepth24Stencil8},
    {DXGI_FORMAT_R16_TYPELESS, DXGI_FORMAT_D16_UNORM, DXGI_FORMAT_R16_UNORM, DepthFormat::Depth16, SurfaceFormat::Depth16},
    {DXGI_FORMAT_R32G8X24_TYPELESS, DXGI_FORMAT_D32_FLOAT_S8X24_UINT, DXGI_FORMAT_R32_FLOAT_X8X24_TYPELESS, DepthFormat::Depth32FStencil8,
     SurfaceFormat::Depth32Stencil8, DXGI_FORMAT_X32_TYPELESS_G8X24_UINT, SurfaceFormat::StencilOfDepth32Stencil8},
};

// A typeless colour format and the typed members its views may name, the first the stored one.
struct ColourFamily {
    DXGI_FORMAT typeless;
    DXGI_FORMAT members[5];  // DXGI_FORMAT_UNKNOWN after the last
};
const ColourFamily kColourFamilies[] = {
    {DXGI_FORMAT_R8G8B8A8_TYPELESS,
     {DXGI_FORMAT_R8G8B8A8_UNORM, DXGI_FORMAT_R8G8B8A8_UNORM_SRGB, DXGI_FORMAT_R8G8B8A8_SNORM, DXGI_FORMAT_R8G8B8A8_UINT, DXGI_FORMAT_R8G8B8A8_SINT}},
    // Each stored in a float or unorm member (renderable and filterable; an upload keeps its bytes).
    {DXGI_FORMAT_R32G32B32A32_TYPELESS, {DXGI_FORMAT_R32G32B32A32_FLOAT, DXGI_FORMAT_R32G32B32A32_UINT, DXGI_FORMAT_R32G32B32A32_SINT}},
    {DXGI_FORMAT_R16G16B16A16_TYPELESS,
     {DXGI_FORMAT_R16G16B16A16_FLOAT, DXGI_FORMAT_R16G16B16A16_UNORM, DXGI_FORMAT_R16G16B16A16_UINT, DXGI_FORMAT_R16G16B16A16_SNORM,
      DXGI_FORMAT_R16G16B16A16_SINT}},
    {DXGI_FORMAT_R32G32_TYPELESS, {DXGI_FORMAT_R32G32_FLOAT, DXGI_FORMAT_R32G32_UINT, DXGI_FORMAT_R32G32_SINT}},
    {DXGI_FORMAT_R16G16_TYPELESS,
     {DXGI_FORMAT_R16G16_FLOAT, DXGI_FORMAT_R16G16_UNORM, DXGI_FORMAT_R16G16_UINT, DXGI_FORMAT_R16G16_SNORM, DXGI_FORMAT_R16G16_SINT}},
    {DXGI_FORMAT_R8G8_TYPELESS, {DXGI_FORMAT_R8G8_UNORM, DXGI_FORMAT_R8G8_UINT, DXGI_FORMAT_R8G8_SNORM, DXGI_FORMAT_R8G8_SINT}},
    {DXGI_FORMAT_R8_TYPELESS, {DXGI_FORMAT_R8_UNORM, DXGI_FORMAT_R8_UINT, DXGI_FORMAT_R8_SINT}},
    {DXGI_FORMAT_B8G8R8A8_TYPELESS, {DXGI_FORMAT_B8G8R8A8_UNORM, DXGI_FORMAT_B8G8R8A8_UNORM_SRGB}},
    {DXGI_FORMAT_B8G8R8X8_TYPELESS, {DXGI_FORMAT_B8G8R8X8_UNORM, DXGI_FORMAT_B8G8R8X8_UNORM_SRGB}},
    {DXGI_FORMAT_BC1_TYPELESS, {DXGI_FORMAT_BC1_UNORM, DXGI_FORMAT_BC1_UNORM_SRGB}},
    {DXGI_FORMAT_BC2_TYPELESS, {DXGI_FORMAT_BC2_UNORM, DXGI_FORMAT_BC2_UNORM_SRGB}},
    {DXGI_FORMAT_BC3_TYPELESS, {DXGI_FORMAT_BC3_UNORM, DXGI_FORMAT_BC3_UNORM_SRGB}},
    {DXGI_FORMAT_BC4_TYPELESS, {DXGI_FORMAT_BC4_UNORM, DXGI_FORMAT_BC4_SNORM}},
    {DXGI_FORMAT_BC5_TYPELESS, {DXGI_FORMAT_BC5_UNORM, DXGI_FORMAT_BC5_SNORM}},
    {DXGI_FORMAT_BC6H_TYPELESS, {DXGI_FORMAT_BC6H_UF16, DXGI_FORMAT_BC6H_SF16}},
    {DXGI_FORMAT_BC7_TYPELESS, {DXGI_FORMAT_BC7_UNORM, DXGI_FORMAT_BC7_UNORM_SRGB}},
};

const ColourFamily* colourFamilyOf(DXGI_FORMAT typeless) {
    for (const ColourFamily& f : kColourFamilies)
        if (f.typeless == typeless) return &f;
    return nullptr;
}

bool isMember(const ColourFamily& family, DXGI_FORMAT format) {
    for (DXGI_FORMAT m : family.members)
        if (m != DXGI_FORMAT_UNKNOWN && m == format) return true;
    return false;
}

}  // namespace

const DepthFamily* depthFamilyOf(DXGI_FORMAT textureFormat) {
    for (const DepthFamily& f : kFamilies)
        if (f.typeless == textureFormat) return &f;
    return nullptr;
}

const DepthFamily* depthFamilyOfView(DXGI_FORMAT depthView) {
    for (const DepthFamily& f : kFamilies)
        if (f.depthView == depthView) return &f;
    return nullptr;
}

bool typelessColourStorage(DXGI_FORMAT typeless, SurfaceFormat& out) {
    const ColourFamily* family = colourFamilyOf(typeless);
    return family && textureFormat(family->members[0], out);
}

SurfaceFormat viewSurface(DXGI_FORMAT viewFormat, const Texture& t) {
    if (const DepthFamily* f = depthFamilyOf(t.desc.Format); f && f->stencilView != DXGI_FORMAT_UNKNOWN && viewFormat == f->stencilView)
        return f->stencil;
    SurfaceFormat s;
    return viewFormat != DXGI_FORMAT_UNKNOWN && colourFamilyOf(t.desc.Format) && textureFormat(viewFormat, s) ? s : t.format;
}

HRESULT checkViewFormat(const char* call, const char* desc, DXGI_FORMAT viewFormat, const Texture& t, bool depthView) {
    if (const ColourFamily* colour = colourFamilyOf(t.desc.Format)) {
        if (isMember(*colour, viewFormat)) return S_OK;
        return fail(E_INVALIDARG, std::string(call) + ": " + desc + ".Format = " + formatName(viewFormat) + " for a " + formatName(t.desc.Format) +
                                      " texture (a typed format of its family: " + formatName(colour->members[0]) + " ...)");
    }
    const DepthFamily* family = depthFamilyOf(t.desc.Format);
    if (!family) {
        if (viewFormat == DXGI_FORMAT_UNKNOWN || viewFormat == t.desc.Format) return S_OK;
        return fail(E_NOTIMPL, std::string(call) + ": " + desc + ".Format = " + formatName(viewFormat) + " differs from the texture's " +
                                   formatName(t.desc.Format) + ": fxport views a texture in its own format (or a typeless depth texture "
                                   "as depth)");
    }
    const DXGI_FORMAT wanted = depthView ? family->depthView : family->sampledView;
    if (viewFormat == wanted) return S_OK;
    // The stencil is read through a shader-resource view of its own format (Texture2D<uint2>, .g).
    const bool stencil = family->stencilView != DXGI_FORMAT_UNKNOWN;
    if (!depthView && stencil && viewFormat == family->stencilView) return S_OK;
    return fail(E_INVALIDARG, std::string(call) + ": " + desc + ".Format = " + formatName(viewFormat) + " for a " + formatName(t.desc.Format) +
                                  " texture (its " + (depthView ? "depth-stencil" : "shader-resource") + " view is " + formatName(wanted) +
                                  (!depthView && stencil ? std::string(", or ") + formatName(family->stencilView) + " for the stencil" : std::string()) + ")");
}

HRESULT checkDepthViewFlags(const std::string& at, UINT flags, DXGI_FORMAT viewFormat) {
    const bool stencil = viewFormat == DXGI_FORMAT_D24_UNORM_S8_UINT || viewFormat == DXGI_FORMAT_D32_FLOAT_S8X24_UINT;
    if ((flags & ~UINT(D3D11_DSV_READ_ONLY_DEPTH | D3D11_DSV_READ_ONLY_STENCIL)) != 0 || ((flags & D3D11_DSV_READ_ONLY_STENCIL) && !stencil))
        return fail(E_INVALIDARG, at + "Flags = " + std::to_string(flags) + " for a " + formatName(viewFormat) + " view (D3D11_DSV_READ_ONLY_DEPTH" +
                                      (stencil ? " | D3D11_DSV_READ_ONLY_STENCIL" : ", the format has no stencil") + ")");
    return S_OK;
}

}  // namespace fxport::d3d11
