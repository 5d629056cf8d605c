// The views of a multisampled array texture (ArraySize > 1 with SampleDesc.Count > 1, a device-core
// MultisampleArray): TEXTURE2DMSARRAY shader-resource views, read by Texture2DMSArray.Load, and
// TEXTURE2DMSARRAY render-target views, drawn into (several slices: SV_RenderTargetArrayIndex picks
// one). Each names slices [FirstArraySlice, FirstArraySlice + ArraySize); a part of the array is a
// GL texture view sharing its samples. ResolveSubresource of one slice is in resources_multisample.cpp.
#include "d3d11_impl.h"
#include "guarded.h"

namespace fxport::d3d11 {

namespace {

// The description a view of the whole array or of the slices `pDesc` names, in `d`; both view kinds
// check alike: only the TEXTURE2DMSARRAY dimension (D3D: a multisampled array is viewed as one, a
// TEXTURE2DARRAY or TEXTURE2DMS view is an error), a format of the texture's family, slices in range,
// and the stored format (`verb`: what fxport does with the texels, for the E_NOTIMPL message).
template <class Desc, class Dimension>
HRESULT decodeMultisampleArrayView(const std::string& call, const std::string& descName, const Texture& t, const Desc* pDesc,
                                   Dimension dimension, const char* dimensionName, const char* verb, Desc& d) {
    const std::string at = call + ": " + descName + ".";
    d.Format = t.desc.Format;
    d.ViewDimension = dimension;
    d.Texture2DMSArray = {0, UINT(t.slices())};
    if (pDesc) {
        if (pDesc->ViewDimension != dimension)
            return fail(E_INVALIDARG, at + "ViewDimension = " + std::to_string(pDesc->ViewDimension) + " for a multisampled array texture (" +
                                          dimensionName + ")");
        if (HRESULT f = checkViewFormat(call.c_str(), descName.c_str(), pDesc->Format, t, false); FAILED(f)) return f;
        const auto& a = pDesc->Texture2DMSArray;
        if (HRESULT f = checkSlices(at + "Texture2DMSArray.", a.FirstArraySlice, a.ArraySize, t.slices()); FAILED(f)) return f;
        d.Texture2DMSArray = a;
        if (pDesc->Format != DXGI_FORMAT_UNKNOWN) d.Format = pDesc->Format;
    }
    if (viewSurface(d.Format, t) != t.format)
        return fail(E_NOTIMPL, at + "Format = " + formatName(d.Format) + " of a " + formatName(t.desc.Format) + " multisampled texture: fxport " +
                                   verb + " those in their stored format only");
    return S_OK;
}

}  // namespace

HRESULT multisampleArrayShaderResourceView(Device* device, Texture* t, const D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc, ID3D11ShaderResourceView** pp) {
    const char* call = "CreateShaderResourceView";
    D3D11_SHADER_RESOURCE_VIEW_DESC d;
    if (HRESULT f = decodeMultisampleArrayView(call, "D3D11_SHADER_RESOURCE_VIEW_DESC", *t, pDesc, D3D11_SRV_DIMENSION_TEXTURE2DMSARRAY,
                                               "D3D11_SRV_DIMENSION_TEXTURE2DMSARRAY", "reads", d);
        FAILED(f))
        return f;
    if (!pp) return succeed();
    return guarded(call, [&] {
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
    const char* call = "CreateRenderTargetView";
    D3D11_RENDER_TARGET_VIEW_DESC d;
    if (HRESULT f = decodeMultisampleArrayView(call, "D3D11_RENDER_TARGET_VIEW_DESC", *t, pDesc, D3D11_RTV_DIMENSION_TEXTURE2DMSARRAY,
                                               "D3D11_RTV_DIMENSION_TEXTURE2DMSARRAY", "writes", d);
        FAILED(f))
        return f;
    if (!pp) return succeed();
    return guarded(call, [&] {
        auto view = std::unique_ptr<RenderTargetView, void (*)(RenderTargetView*)>(new RenderTargetView(device, t, d),
                                                                                   [](RenderTargetView* v) { v->Release(); });
        const auto& a = d.Texture2DMSArray;
        view->slice = std::make_unique<RenderTarget2D>(*t->array, int(a.FirstArraySlice), 0, int(a.ArraySize));  // multisampled, as the array
        *pp = view.release();
        return succeed();
    });
}

}  // namespace fxport::d3d11
