// Shader-resource, render-target and depth-stencil views of 2D textures (the whole texture: one
// format, all levels for SRVs, level 0 for RTVs and DSVs).
#include "d3d11_impl.h"
#include "guarded.h"

namespace fxport::d3d11 {

namespace {

// The texture behind `resource`, or null with the failure (and its message) in `hr`.
Texture* textureOf(Device* device, ID3D11Resource* resource, const char* call, HRESULT& hr) {
    hr = S_OK;
    if (!resource) {
        hr = fail(E_INVALIDARG, std::string(call) + ": pResource is null");
        return nullptr;
    }
    if (dynamic_cast<Buffer*>(resource)) {
        hr = fail(E_NOTIMPL, std::string(call) + ": views of buffers are not supported yet");
        return nullptr;
    }
    auto* t = dynamic_cast<Texture*>(resource);
    if (!t || &t->device() != device) {
        hr = fail(E_INVALIDARG, std::string(call) + ": pResource was not made by this device");
        return nullptr;
    }
    return t;
}

HRESULT checkFormat(const char* call, const char* desc, DXGI_FORMAT viewFormat, const Texture& t) {
    if (viewFormat == DXGI_FORMAT_UNKNOWN || viewFormat == t.desc.Format) return S_OK;
    return fail(E_NOTIMPL, std::string(call) + ": " + desc + ".Format = " + formatName(viewFormat) + " differs from the texture's " +
                               formatName(t.desc.Format) + ": fxport views a texture in its own format");
}

}  // namespace

HRESULT Device::CreateShaderResourceView(ID3D11Resource* pResource, const D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc,
                                         ID3D11ShaderResourceView** ppSRView) {
    const char* call = "CreateShaderResourceView";
    HRESULT hr;
    Texture* t = textureOf(this, pResource, call, hr);
    if (!t) return hr;
    if (!(t->desc.BindFlags & D3D11_BIND_SHADER_RESOURCE))
        return fail(E_INVALIDARG, std::string(call) + ": the texture's BindFlags = " + std::to_string(t->desc.BindFlags) +
                                      " lack D3D11_BIND_SHADER_RESOURCE");
    D3D11_SHADER_RESOURCE_VIEW_DESC d;
    d.Format = t->desc.Format;
    d.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2D;
    d.Texture2D.MipLevels = t->desc.MipLevels;
    if (pDesc) {
        if (pDesc->ViewDimension != D3D11_SRV_DIMENSION_TEXTURE2D)
            return fail(pDesc->ViewDimension == D3D11_SRV_DIMENSION_UNKNOWN ? E_INVALIDARG : E_NOTIMPL,
                        std::string(call) + ": D3D11_SHADER_RESOURCE_VIEW_DESC.ViewDimension = " + std::to_string(pDesc->ViewDimension) +
                            " (fxport views 2D textures as D3D11_SRV_DIMENSION_TEXTURE2D)");
        if (HRESULT f = checkFormat(call, "D3D11_SHADER_RESOURCE_VIEW_DESC", pDesc->Format, *t); FAILED(f)) return f;
        const UINT levels = pDesc->Texture2D.MipLevels;
        if (pDesc->Texture2D.MostDetailedMip != 0 || (levels != UINT(-1) && levels != t->desc.MipLevels))
            return fail(E_NOTIMPL, std::string(call) + ": D3D11_SHADER_RESOURCE_VIEW_DESC.Texture2D = {MostDetailedMip " +
                                       std::to_string(pDesc->Texture2D.MostDetailedMip) + ", MipLevels " + std::to_string(levels) +
                                       "}: fxport views every level (0, -1)");
    }
    if (!ppSRView) return succeed();
    *ppSRView = new ShaderResourceView(this, t, d);
    return succeed();
}

HRESULT Device::CreateRenderTargetView(ID3D11Resource* pResource, const D3D11_RENDER_TARGET_VIEW_DESC* pDesc,
                                       ID3D11RenderTargetView** ppRTView) {
    const char* call = "CreateRenderTargetView";
    HRESULT hr;
    Texture* t = textureOf(this, pResource, call, hr);
    if (!t) return hr;
    if (!(t->desc.BindFlags & D3D11_BIND_RENDER_TARGET))
        return fail(E_INVALIDARG, std::string(call) + ": the texture's BindFlags = " + std::to_string(t->desc.BindFlags) +
                                      " lack D3D11_BIND_RENDER_TARGET");
    D3D11_RENDER_TARGET_VIEW_DESC d;
    d.Format = t->desc.Format;
    d.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2D;
    if (pDesc) {
        if (pDesc->ViewDimension != D3D11_RTV_DIMENSION_TEXTURE2D)
            return fail(pDesc->ViewDimension == D3D11_RTV_DIMENSION_UNKNOWN ? E_INVALIDARG : E_NOTIMPL,
                        std::string(call) + ": D3D11_RENDER_TARGET_VIEW_DESC.ViewDimension = " + std::to_string(pDesc->ViewDimension));
        if (HRESULT f = checkFormat(call, "D3D11_RENDER_TARGET_VIEW_DESC", pDesc->Format, *t); FAILED(f)) return f;
        if (pDesc->Texture2D.MipSlice != 0)
            return fail(E_NOTIMPL, std::string(call) + ": D3D11_RENDER_TARGET_VIEW_DESC.Texture2D.MipSlice = " +
                                       std::to_string(pDesc->Texture2D.MipSlice) + ": fxport renders into level 0");
    }
    if (!ppRTView) return succeed();
    *ppRTView = new RenderTargetView(this, t, d);
    return succeed();
}

HRESULT Device::CreateDepthStencilView(ID3D11Resource* pResource, const D3D11_DEPTH_STENCIL_VIEW_DESC* pDesc,
                                       ID3D11DepthStencilView** ppDepthStencilView) {
    const char* call = "CreateDepthStencilView";
    HRESULT hr;
    Texture* t = textureOf(this, pResource, call, hr);
    if (!t) return hr;
    if (!t->depth)
        return fail(E_INVALIDARG, std::string(call) + ": the texture's BindFlags = " + std::to_string(t->desc.BindFlags) +
                                      " lack D3D11_BIND_DEPTH_STENCIL");
    D3D11_DEPTH_STENCIL_VIEW_DESC d;
    d.Format = t->desc.Format;
    d.ViewDimension = D3D11_DSV_DIMENSION_TEXTURE2D;
    if (pDesc) {
        if (pDesc->ViewDimension != D3D11_DSV_DIMENSION_TEXTURE2D)
            return fail(pDesc->ViewDimension == D3D11_DSV_DIMENSION_UNKNOWN ? E_INVALIDARG : E_NOTIMPL,
                        std::string(call) + ": D3D11_DEPTH_STENCIL_VIEW_DESC.ViewDimension = " + std::to_string(pDesc->ViewDimension));
        if (HRESULT f = checkFormat(call, "D3D11_DEPTH_STENCIL_VIEW_DESC", pDesc->Format, *t); FAILED(f)) return f;
        if (pDesc->Flags != 0)
            return fail(E_NOTIMPL, std::string(call) + ": D3D11_DEPTH_STENCIL_VIEW_DESC.Flags = " + std::to_string(pDesc->Flags) +
                                       ": read-only depth views are not supported yet");
        if (pDesc->Texture2D.MipSlice != 0)
            return fail(E_INVALIDARG, std::string(call) + ": D3D11_DEPTH_STENCIL_VIEW_DESC.Texture2D.MipSlice = " +
                                          std::to_string(pDesc->Texture2D.MipSlice) + " (the texture has 1 level)");
    }
    if (!ppDepthStencilView) return succeed();
    *ppDepthStencilView = new DepthStencilView(this, t, d);
    return succeed();
}

HRESULT Device::CreateUnorderedAccessView(ID3D11Resource*, const void*, ID3D11UnorderedAccessView**) {
    return fail(E_NOTIMPL, "CreateUnorderedAccessView: unordered-access views (compute) are not implemented in the D3D11 front end yet");
}

}  // namespace fxport::d3d11
