// The views of a multisampled array texture (ArraySize > 1 with SampleDesc.Count > 1, a device-core
// MultisampleArray): TEXTURE2DMSARRAY shader-resource views, read by Texture2DMSArray.Load, and
// TEXTURE2DMSARRAY render-target views, drawn into (several slices: SV_RenderTargetArrayIndex picks
// one). Each names slices [FirstArraySlice, FirstArraySlice + ArraySize); a part of the array is a
// GL texture view sharing its samples. ResolveSubresource of one slice is in resources_multisample.cpp.
#include "d3d11_impl.h"
#include "guarded.h"

namespace fxport::d3d11 {

HRESULT multisampleArrayShaderResourceView(Device* device, Texture* t, const D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc, ID3D11ShaderResourceView** pp) {
    const std::string call = "CreateShaderResourceView", at = call + ": D3D11_SHADER_RESOURCE_VIEW_DESC.";
    D3D11_SHADER_RESOURCE_VIEW_DESC d;
    d.Format = t->desc.Format;
    d.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2DMSARRAY;
    d.Texture2DMSArray = {0, UINT(t->slices())};
    if (pDesc) {
        // D3D: a multisampled array is viewed as one (a TEXTURE2DARRAY or TEXTURE2DMS view is an error).
        if (pDesc->ViewDimension != D3D11_SRV_DIMENSION_TEXTURE2DMSARRAY)
            return fail(E_INVALIDARG, at + "ViewDimension = " + std::to_string(pDesc->ViewDimension) +
                                          " for a multisampled array texture (D3D11_SRV_DIMENSION_TEXTURE2DMSARRAY)");
        if (HRESULT f = checkViewFormat(call.c_str(), "D3D11_SHADER_RESOURCE_VIEW_DESC", pDesc->Format, *t, false); FAILED(f)) return f;
        const auto& a = pDesc->Texture2DMSArray;
        if (HRESULT f = checkSlices(at + "Texture2DMSArray.", a.FirstArraySlice, a.ArraySize, t->slices()); FAILED(f)) return f;
        d.Texture2DMSArray = a;
        if (pDesc->Format != DXGI_FORMAT_UNKNOWN) d.Format = pDesc->Format;
    }
    if (viewSurface(d.Format, *t) != t->format)
        return fail(E_NOTIMPL, at + "Format = " + formatName(d.Format) + " of a " + formatName(t->desc.Format) +
                                   " multisampled texture: fxport reads those in their stored format only");
    if (!pp) return succeed();
    return guarded(call.c_str(), [&] {
        auto view = std::unique_ptr<ShaderResourceView, void (*)(ShaderResourceView*)>(new ShaderResourceView(device, t, d),
                                                                                       [](ShaderResourceView* v) { v->Release(); });
        const auto& a = d.Texture2DMSArray;
        if (a.FirstArraySlice != 0 || a.ArraySize != UINT(t->slices()))
            view->arrayRange = std::make_unique<fxport::Texture2DArray>(*t->array, 0, 1, int(a.FirstArraySlice), int(a.ArraySize));
        *pp = view.release();
        return succeed();
    });
}

HRESULT multisampleArrayRenderTargetView(Device* device, Texture* t, const D3D11_RENDER_TARGET_VIEW_DESC* pDesc, ID3D11RenderTargetView** pp) {
    const std::string call = "CreateRenderTargetView", at = call + ": D3D11_RENDER_TARGET_VIEW_DESC.";
    D3D11_RENDER_TARGET_VIEW_DESC d;
    d.Format = t->desc.Format;
    d.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2DMSARRAY;
    d.Texture2DMSArray = {0, UINT(t->slices())};
    if (pDesc) {
        if (pDesc->ViewDimension != D3D11_RTV_DIMENSION_TEXTURE2DMSARRAY)
            return fail(E_INVALIDARG, at + "ViewDimension = " + std::to_string(pDesc->ViewDimension) +
                                          " for a multisampled array texture (D3D11_RTV_DIMENSION_TEXTURE2DMSARRAY)");
        if (HRESULT f = checkViewFormat(call.c_str(), "D3D11_RENDER_TARGET_VIEW_DESC", pDesc->Format, *t, false); FAILED(f)) return f;
        const auto& a = pDesc->Texture2DMSArray;
        if (HRESULT f = checkSlices(at + "Texture2DMSArray.", a.FirstArraySlice, a.ArraySize, t->slices()); FAILED(f)) return f;
        d.Texture2DMSArray = a;
        if (pDesc->Format != DXGI_FORMAT_UNKNOWN) d.Format = pDesc->Format;
    }
    if (viewSurface(d.Format, *t) != t->format)
        return fail(E_NOTIMPL, at + "Format = " + formatName(d.Format) + " of a " + formatName(t->desc.Format) +
                                   " multisampled texture: fxport writes those in their stored format only");
    if (!pp) return succeed();
    return guarded(call.c_str(), [&] {
        auto view = std::unique_ptr<RenderTargetView, void (*)(RenderTargetView*)>(new RenderTargetView(device, t, d),
                                                                                   [](RenderTargetView* v) { v->Release(); });
        const auto& a = d.Texture2DMSArray;
        view->slice = std::make_unique<RenderTarget2D>(*t->array, int(a.FirstArraySlice), 0, int(a.ArraySize));  // multisampled, as the array
        *pp = view.release();
        return succeed();
    });
}

}  // namespace fxport::d3d11
