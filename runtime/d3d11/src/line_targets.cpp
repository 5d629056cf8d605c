// Render-target and depth-stencil views of 1D textures (D3D11_RTV/DSV_DIMENSION_TEXTURE1D and
// TEXTURE1DARRAY): one level's rows, drawn into as a target one texel high -- GL attaches a 1D
// texture to a framebuffer as such an image, and a 1D array layered, where SV_RenderTargetArrayIndex
// picks the row. The core's RenderTarget2D / DepthBuffer over a GL view of the rows
// (Texture1D::rowView) keep binding, clears and draws on their 2D paths.
#include "d3d11_impl.h"
#include "guarded.h"

namespace fxport::d3d11 {

namespace {

// The rows a view names: MipSlice, FirstArraySlice, ArraySize (a TEXTURE1D view: slice 0 of a
// single texture).
struct Rows {
    UINT level = 0, first = 0, count = 1;
};

// The view's dimension and rows from its description (`Desc`: D3D11_RENDER_TARGET_VIEW_DESC or
// D3D11_DEPTH_STENCIL_VIEW_DESC, whose 1D members have the same fields); E_INVALIDARG naming the field.
template <class Desc, class Dimension>
HRESULT rowsOf(const std::string& at, const LineTexture& t, const Desc& given, Dimension oneD, Dimension array, Rows& rows) {
    if (given.ViewDimension != oneD && given.ViewDimension != array)
        return fail(E_INVALIDARG, at + "ViewDimension = " + std::to_string(given.ViewDimension) + " for a 1D texture (TEXTURE1D or TEXTURE1DARRAY)");
    if (given.ViewDimension == oneD && t.desc.ArraySize > 1) return fail(E_INVALIDARG, at + "ViewDimension = TEXTURE1D for an array (TEXTURE1DARRAY)");
    const DepthFamily* typeless = depthFamilyOf(t.desc.Format);  // a sampled depth texture: its DSV names the depth format
    if (typeless && given.Format != typeless->depthView)
        return fail(E_INVALIDARG, at + "Format = " + formatName(given.Format) + " for a " + formatName(t.desc.Format) + " 1D texture (its depth-stencil view is " +
                                      formatName(typeless->depthView) + ")");
    if (!typeless && given.Format != DXGI_FORMAT_UNKNOWN && given.Format != t.desc.Format)
        return fail(E_NOTIMPL, at + "Format = " + formatName(given.Format) + " for a " + formatName(t.desc.Format) + " 1D texture: fxport views it in its own format");
    rows = given.ViewDimension == oneD ? Rows{given.Texture1D.MipSlice, 0, 1}
                                       : Rows{given.Texture1DArray.MipSlice, given.Texture1DArray.FirstArraySlice, given.Texture1DArray.ArraySize};
    if (rows.level >= UINT(t.levels))
        return fail(E_INVALIDARG, at + "MipSlice = " + std::to_string(rows.level) + " (the texture has " + std::to_string(t.levels) + " levels)");
    if (rows.count == 0 || rows.first >= t.desc.ArraySize || rows.count > t.desc.ArraySize - rows.first)
        return fail(E_INVALIDARG, at + "Texture1DArray.FirstArraySlice + ArraySize = " + std::to_string(rows.first) + " + " + std::to_string(rows.count) +
                                      " (the texture has " + std::to_string(t.desc.ArraySize) + " slices)");
    return S_OK;
}

HRESULT lacksBind(const char* call, const LineTexture& t, const char* flag) {
    return fail(E_INVALIDARG, std::string(call) + ": the texture's BindFlags = " + std::to_string(t.desc.BindFlags) + " lack " + flag);
}

}  // namespace

HRESULT lineRenderTargetView(Device* device, LineTexture* t, const D3D11_RENDER_TARGET_VIEW_DESC* pDesc, ID3D11RenderTargetView** pp) {
    const char* call = "CreateRenderTargetView";
    if (!(t->desc.BindFlags & D3D11_BIND_RENDER_TARGET)) return lacksBind(call, *t, "D3D11_BIND_RENDER_TARGET");
    D3D11_RENDER_TARGET_VIEW_DESC d;
    d.Format = t->desc.Format;
    d.ViewDimension = t->desc.ArraySize > 1 ? D3D11_RTV_DIMENSION_TEXTURE1DARRAY : D3D11_RTV_DIMENSION_TEXTURE1D;
    d.Texture1DArray = {0, 0, t->desc.ArraySize};
    Rows rows{0, 0, t->desc.ArraySize};
    if (pDesc) {
        const std::string at = std::string(call) + ": D3D11_RENDER_TARGET_VIEW_DESC.";
        if (HRESULT hr = rowsOf(at, *t, *pDesc, D3D11_RTV_DIMENSION_TEXTURE1D, D3D11_RTV_DIMENSION_TEXTURE1DARRAY, rows); FAILED(hr)) return hr;
        d.ViewDimension = pDesc->ViewDimension;
        d.Texture1D = {rows.level};
        d.Texture1DArray = {rows.level, rows.first, rows.count};
    }
    if (!pp) return succeed();
    return guarded(call, [&] {
        auto view = std::unique_ptr<RenderTargetView, void (*)(RenderTargetView*)>(new RenderTargetView(device, t, d),
                                                                                   [](RenderTargetView* v) { v->Release(); });
        view->slice = std::make_unique<RenderTarget2D>(*t->texels, int(rows.first), int(rows.level), int(rows.count));
        *pp = view.release();
        return succeed();
    });
}

HRESULT lineDepthStencilView(Device* device, LineTexture* t, const D3D11_DEPTH_STENCIL_VIEW_DESC* pDesc, ID3D11DepthStencilView** pp) {
    const char* call = "CreateDepthStencilView";
    if (!(t->desc.BindFlags & D3D11_BIND_DEPTH_STENCIL)) return lacksBind(call, *t, "D3D11_BIND_DEPTH_STENCIL");
    if (!pDesc && depthFamilyOf(t->desc.Format))
        return fail(E_INVALIDARG, std::string(call) + ": pDesc is null for a " + formatName(t->desc.Format) + " texture (a typeless texture's view names its Format)");
    D3D11_DEPTH_STENCIL_VIEW_DESC d;
    d.Format = t->desc.Format;
    d.ViewDimension = t->desc.ArraySize > 1 ? D3D11_DSV_DIMENSION_TEXTURE1DARRAY : D3D11_DSV_DIMENSION_TEXTURE1D;
    d.Texture1DArray = {0, 0, t->desc.ArraySize};
    Rows rows{0, 0, t->desc.ArraySize};
    if (pDesc) {
        const std::string at = std::string(call) + ": D3D11_DEPTH_STENCIL_VIEW_DESC.";
        if (HRESULT hr = rowsOf(at, *t, *pDesc, D3D11_DSV_DIMENSION_TEXTURE1D, D3D11_DSV_DIMENSION_TEXTURE1DARRAY, rows); FAILED(hr)) return hr;
        const DXGI_FORMAT viewed = pDesc->Format != DXGI_FORMAT_UNKNOWN ? pDesc->Format : t->desc.Format;
        if (HRESULT hr = checkDepthViewFlags(at, pDesc->Flags, viewed); FAILED(hr)) return hr;
        d.Format = viewed;
        d.ViewDimension = pDesc->ViewDimension;
        d.Flags = pDesc->Flags;
        d.Texture1D = {rows.level};
        d.Texture1DArray = {rows.level, rows.first, rows.count};
    }
    if (!pp) return succeed();
    return guarded(call, [&] {
        auto view = std::unique_ptr<DepthStencilView, void (*)(DepthStencilView*)>(new DepthStencilView(device, t, d),
                                                                                   [](DepthStencilView* v) { v->Release(); });
        view->sliceTexture = std::make_unique<fxport::Texture2D>(*t->texels, int(rows.first), int(rows.level), int(rows.count));
        view->slice = std::make_unique<core::DepthBuffer>(device->core(), *view->sliceTexture);
        *pp = view.release();
        return succeed();
    });
}

}  // namespace fxport::d3d11
