// The typeless depth formats D3D programs make shadow maps of: a texture of R32_TYPELESS,
// R24G8_TYPELESS or R16_TYPELESS is written through a depth-stencil view (D32_FLOAT,
// D24_UNORM_S8_UINT, D16_UNORM) and read through a shader-resource view (R32_FLOAT,
// R24_UNORM_X8_TYPELESS, R16_UNORM) -- one depth texture underneath. These are the only view
// casts fxport makes; other typeless formats are refused (formats.cpp does not map them).
#include "d3d11_impl.h"

namespace fxport::d3d11 {

namespace {

const DepthFamily kFamilies[] = {
    {DXGI_FORMAT_R32_TYPELESS, DXGI_FORMAT_D32_FLOAT, DXGI_FORMAT_R32_FLOAT, DepthFormat::Depth32F, SurfaceFormat::Depth32},
    {DXGI_FORMAT_R24G8_TYPELESS, DXGI_FORMAT_D24_UNORM_S8_UINT, DXGI_FORMAT_R24_UNORM_X8_TYPELESS, DepthFormat::Depth24Stencil8,
     SurfaceFormat::Depth24Stencil8},
    {DXGI_FORMAT_R16_TYPELESS, DXGI_FORMAT_D16_UNORM, DXGI_FORMAT_R16_UNORM, DepthFormat::Depth16, SurfaceFormat::Depth16},
};

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

HRESULT checkViewFormat(const char* call, const char* desc, DXGI_FORMAT viewFormat, const Texture& t, bool depthView) {
    const DepthFamily* family = depthFamilyOf(t.desc.Format);
    if (!family) {
        if (viewFormat == DXGI_FORMAT_UNKNOWN || viewFormat == t.desc.Format) return S_OK;
        return fail(E_NOTIMPL, std::string(call) + ": " + desc + ".Format = " + formatName(viewFormat) + " differs from the texture's " +
                                   formatName(t.desc.Format) + ": fxport views a texture in its own format (or a typeless depth texture "
                                   "as depth)");
    }
    const DXGI_FORMAT wanted = depthView ? family->depthView : family->sampledView;
    if (viewFormat == wanted) return S_OK;
    return fail(E_INVALIDARG, std::string(call) + ": " + desc + ".Format = " + formatName(viewFormat) + " for a " + formatName(t.desc.Format) +
                                  " texture (its " + (depthView ? "depth-stencil" : "shader-resource") + " view is " + formatName(wanted) + ")");
}

HRESULT checkDepthViewFlags(const std::string& at, UINT flags, DXGI_FORMAT viewFormat) {
    const bool stencil = viewFormat == DXGI_FORMAT_D24_UNORM_S8_UINT;  // the one stencil format fxport has
    if ((flags & ~UINT(D3D11_DSV_READ_ONLY_DEPTH | D3D11_DSV_READ_ONLY_STENCIL)) != 0 || ((flags & D3D11_DSV_READ_ONLY_STENCIL) && !stencil))
        return fail(E_INVALIDARG, at + "Flags = " + std::to_string(flags) + " for a " + formatName(viewFormat) + " view (D3D11_DSV_READ_ONLY_DEPTH" +
                                      (stencil ? " | D3D11_DSV_READ_ONLY_STENCIL" : ", the format has no stencil") + ")");
    return S_OK;
}

}  // namespace fxport::d3d11
