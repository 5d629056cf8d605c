// 1D textures: CreateTexture1D and their shader-resource (TEXTURE1D, TEXTURE1DARRAY) and
// unordered-access views. A 1D texture is a device-core Texture1D -- GL's 1D texture for
// ArraySize 1, its 1D array texture for more, as HLSL's Texture1D and Texture1DArray sample them --
// or CPU memory (USAGE_STAGING). Its subresources are rows: level + slice * MipLevels, each
// pInitialData entry one row (SysMemPitch unused, as in D3D).
#include <algorithm>

#include "d3d11_impl.h"
#include "guarded.h"

namespace fxport::d3d11 {

namespace {

constexpr UINT kMaxWidth = 16384;  // D3D11_REQ_TEXTURE1D_U_DIMENSION
constexpr UINT kMaxSlices = 2048;  // D3D11_REQ_TEXTURE1D_ARRAY_AXIS_DIMENSION

int fullLineMipCount(UINT width) { return fullMipCount(width, 1); }

HRESULT checkLineShape(const D3D11_TEXTURE1D_DESC& d, const std::string& at) {
    if (d.Width == 0 || d.Width > kMaxWidth) return fail(E_INVALIDARG, at + "Width = " + std::to_string(d.Width) + " (1 to 16384)");
    if (d.ArraySize == 0 || d.ArraySize > kMaxSlices) return fail(E_INVALIDARG, at + "ArraySize = " + std::to_string(d.ArraySize) + " (1 to 2048)");
    const int full = fullLineMipCount(d.Width);
    if (int(d.MipLevels) > full)
        return fail(E_INVALIDARG, at + "MipLevels = " + std::to_string(d.MipLevels) + " (a " + std::to_string(d.Width) + "-texel texture has at most " +
                                      std::to_string(full) + ")");
    return S_OK;
}

// Binds, usage and misc flags: shader resources, UAVs and render targets, or a depth-stencil
// texture (sampled too when typeless); D3D's usage rules (checkUsage), GENERATE_MIPS only.
HRESULT checkLineUse(const D3D11_TEXTURE1D_DESC& d, bool hasData, const std::string& at) {
    const UINT known = D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_UNORDERED_ACCESS | D3D11_BIND_RENDER_TARGET | D3D11_BIND_DEPTH_STENCIL;
    if (d.BindFlags & ~known)
        return fail(E_INVALIDARG, at + "BindFlags = " + std::to_string(d.BindFlags) +
                                      ": a 1D texture is bound as SHADER_RESOURCE, UNORDERED_ACCESS, RENDER_TARGET or DEPTH_STENCIL");
    if ((d.BindFlags & D3D11_BIND_DEPTH_STENCIL) && (d.BindFlags & (D3D11_BIND_RENDER_TARGET | D3D11_BIND_UNORDERED_ACCESS)))
        return fail(E_INVALIDARG, at + "BindFlags = " + std::to_string(d.BindFlags) +
                                      ": a depth-stencil texture is DEPTH_STENCIL (and SHADER_RESOURCE), not a render target or UAV");
    if ((d.BindFlags & D3D11_BIND_DEPTH_STENCIL) && hasData) return fail(E_INVALIDARG, at + "BindFlags has DEPTH_STENCIL and pInitialData is given");
    if ((d.BindFlags & D3D11_BIND_UNORDERED_ACCESS) && d.Usage != D3D11_USAGE_DEFAULT)
        return fail(E_INVALIDARG, at + "Usage = " + std::to_string(d.Usage) + " with BIND_UNORDERED_ACCESS (must be USAGE_DEFAULT)");
    // D3D11: a dynamic texture is one level of one slice.
    if (d.Usage == D3D11_USAGE_DYNAMIC && (d.ArraySize != 1 || d.MipLevels != 1))
        return fail(E_INVALIDARG, at + "Usage = D3D11_USAGE_DYNAMIC with ArraySize = " + std::to_string(d.ArraySize) + ", MipLevels = " +
                                      std::to_string(d.MipLevels) + " (a dynamic texture has one of each)");
    if (HRESULT hr = checkUsage("CreateTexture1D", "D3D11_TEXTURE1D_DESC", d.Usage, d.BindFlags, d.CPUAccessFlags, hasData); FAILED(hr)) return hr;
    if (d.MiscFlags & ~UINT(D3D11_RESOURCE_MISC_GENERATE_MIPS))
        return fail(E_NOTIMPL, at + "MiscFlags = " + std::to_string(d.MiscFlags) + ": a 1D texture takes D3D11_RESOURCE_MISC_GENERATE_MIPS only");
    if ((d.MiscFlags & D3D11_RESOURCE_MISC_GENERATE_MIPS) && !(d.BindFlags & D3D11_BIND_SHADER_RESOURCE))
        return fail(E_INVALIDARG, at + "MiscFlags = D3D11_RESOURCE_MISC_GENERATE_MIPS without BIND_SHADER_RESOURCE");
    return S_OK;
}

HRESULT checkLineFormat(const D3D11_TEXTURE1D_DESC& d, SurfaceFormat& format, const std::string& at) {
    // D32_FLOAT, D24_UNORM_S8_UINT ...: a depth texture the DSV draws into; R32_TYPELESS ... with
    // SHADER_RESOURCE too: the same depth texture, read through an R32_FLOAT ... view (a 1D shadow map).
    if (d.BindFlags & D3D11_BIND_DEPTH_STENCIL) {
        const DepthFamily* family = depthFamilyOf(d.Format);
        if (!family) family = depthFamilyOfView(d.Format);
        if (!family) return fail(E_INVALIDARG, at + "Format = " + formatName(d.Format) + " with BIND_DEPTH_STENCIL: not a depth format");
        if ((d.BindFlags & D3D11_BIND_SHADER_RESOURCE) && family->typeless != d.Format)
            return fail(E_INVALIDARG, at + "BindFlags = " + std::to_string(d.BindFlags) + " with Format = " + formatName(d.Format) +
                                          ": a depth texture a shader samples is made typeless (" + formatName(family->typeless) + ")");
        format = family->sampled;
        return S_OK;
    }
    if (!textureFormat(d.Format, format) || depthFamilyOf(d.Format) || isCompressedFormat(format))
        return fail(d.Format == DXGI_FORMAT_UNKNOWN || (textureFormat(d.Format, format) && isCompressedFormat(format)) ? E_INVALIDARG : E_NOTIMPL,
                    at + "Format = " + formatName(d.Format) + " (" + std::to_string(d.Format) +
                        "): not a 1D texture format fxport supports (docs/API.md lists them; block-compressed formats are 2D)");
    if ((d.MiscFlags & D3D11_RESOURCE_MISC_GENERATE_MIPS) && isIntegerFormat(format))
        return fail(E_INVALIDARG, at + "MiscFlags = D3D11_RESOURCE_MISC_GENERATE_MIPS with Format = " + formatName(d.Format) +
                                      ": integer texels cannot be filtered into smaller levels");
    return S_OK;
}

HRESULT fillLines(LineTexture& t, const D3D11_SUBRESOURCE_DATA* initial) {
    for (int sub = 0; sub < t.subresources(); ++sub) {
        if (!initial[sub].pSysMem) return fail(E_INVALIDARG, "CreateTexture1D: pInitialData[" + std::to_string(sub) + "].pSysMem is null");
        writeLine(t, sub, 0, static_cast<const std::uint8_t*>(initial[sub].pSysMem), t.levelWidth(sub % t.levels));
    }
    return S_OK;
}

// The levels [first, first + count) a view names (count -1: to the last), inside the texture's.
HRESULT checkViewLevels(const std::string& at, UINT first, UINT& count, int levels) {
    if (first >= UINT(levels))
        return fail(E_INVALIDARG, at + "MostDetailedMip = " + std::to_string(first) + " (the texture has " + std::to_string(levels) + " levels)");
    if (count == UINT(-1)) count = UINT(levels) - first;
    if (count == 0 || count > UINT(levels) - first)
        return fail(E_INVALIDARG, at + "MipLevels = " + std::to_string(count) + " from MostDetailedMip " + std::to_string(first) + " (the texture has " +
                                      std::to_string(levels) + " levels)");
    return S_OK;
}

HRESULT checkViewSlices(const std::string& at, UINT first, UINT count, UINT slices) {
    if (count == 0 || first >= slices || count > slices - first)
        return fail(E_INVALIDARG, at + "FirstArraySlice + ArraySize = " + std::to_string(first) + " + " + std::to_string(count) + " (the texture has " +
                                      std::to_string(slices) + " slices)");
    return S_OK;
}

HRESULT checkLineViewFormat(const std::string& at, DXGI_FORMAT viewFormat, const LineTexture& t) {
    if (const DepthFamily* family = depthFamilyOf(t.desc.Format)) {  // a typeless depth texture: its depth view
        if (viewFormat == family->sampledView) return S_OK;
        return fail(viewFormat == family->stencilView && viewFormat != DXGI_FORMAT_UNKNOWN ? E_NOTIMPL : E_INVALIDARG,
                    at + "Format = " + formatName(viewFormat) + " for a " + formatName(t.desc.Format) + " 1D texture (its shader-resource view is " +
                        formatName(family->sampledView) + "; a 1D stencil view: not yet)");
    }
    if (viewFormat == DXGI_FORMAT_UNKNOWN || viewFormat == t.desc.Format) return S_OK;
    return fail(E_NOTIMPL, at + "Format = " + formatName(viewFormat) + " for a " + formatName(t.desc.Format) + " 1D texture: fxport views it in its own format");
}

// The view's description with its defaults filled in: the whole texture, as a 1D texture for one
// slice and a 1D array for more (D3D's defaults).
D3D11_SHADER_RESOURCE_VIEW_DESC defaultLineView(const LineTexture& t) {
    D3D11_SHADER_RESOURCE_VIEW_DESC d;
    d.Format = t.desc.Format;
    d.ViewDimension = t.desc.ArraySize > 1 ? D3D11_SRV_DIMENSION_TEXTURE1DARRAY : D3D11_SRV_DIMENSION_TEXTURE1D;
    d.Texture1D = {0, UINT(t.levels)};
    d.Texture1DArray = {0, UINT(t.levels), 0, t.desc.ArraySize};
    return d;
}

HRESULT checkLineSrv(const LineTexture& t, const D3D11_SHADER_RESOURCE_VIEW_DESC& given, D3D11_SHADER_RESOURCE_VIEW_DESC& d) {
    const std::string at = "CreateShaderResourceView: D3D11_SHADER_RESOURCE_VIEW_DESC.";
    if (given.ViewDimension != D3D11_SRV_DIMENSION_TEXTURE1D && given.ViewDimension != D3D11_SRV_DIMENSION_TEXTURE1DARRAY)
        return fail(E_INVALIDARG, at + "ViewDimension = " + std::to_string(given.ViewDimension) +
                                      " for a 1D texture (D3D11_SRV_DIMENSION_TEXTURE1D or TEXTURE1DARRAY)");
    if (HRESULT hr = checkLineViewFormat(at, given.Format, t); FAILED(hr)) return hr;
    d.ViewDimension = given.ViewDimension;
    if (given.ViewDimension == D3D11_SRV_DIMENSION_TEXTURE1D) {
        if (t.desc.ArraySize > 1) return fail(E_INVALIDARG, at + "ViewDimension = D3D11_SRV_DIMENSION_TEXTURE1D for an array (TEXTURE1DARRAY)");
        d.Texture1D = given.Texture1D;
        return checkViewLevels(at + "Texture1D.", d.Texture1D.MostDetailedMip, d.Texture1D.MipLevels, t.levels);
    }
    d.Texture1DArray = given.Texture1DArray;
    if (HRESULT hr = checkViewLevels(at + "Texture1DArray.", d.Texture1DArray.MostDetailedMip, d.Texture1DArray.MipLevels, t.levels); FAILED(hr))
        return hr;
    return checkViewSlices(at + "Texture1DArray.", d.Texture1DArray.FirstArraySlice, d.Texture1DArray.ArraySize, t.desc.ArraySize);
}

}  // namespace

HRESULT Device::CreateTexture1D(const D3D11_TEXTURE1D_DESC* pDesc, const D3D11_SUBRESOURCE_DATA* pInitialData, ID3D11Texture1D** ppTexture1D) {
    const char* call = "CreateTexture1D";
    if (!pDesc) return fail(E_INVALIDARG, "CreateTexture1D: pDesc is null");
    const D3D11_TEXTURE1D_DESC& d = *pDesc;
    const std::string at = "CreateTexture1D: D3D11_TEXTURE1D_DESC.";
    SurfaceFormat format = SurfaceFormat::Color;
    if (HRESULT hr = checkLineShape(d, at); FAILED(hr)) return hr;
    if (HRESULT hr = checkLineUse(d, pInitialData && pInitialData->pSysMem, at); FAILED(hr)) return hr;
    if (HRESULT hr = checkLineFormat(d, format, at); FAILED(hr)) return hr;
    if (!ppTexture1D) return succeed();  // D3D: validation only
    return guarded(call, [&] {
        auto texture = std::unique_ptr<LineTexture, void (*)(LineTexture*)>(new LineTexture(this, d), [](LineTexture* t) { t->Release(); });
        LineTexture& t = *texture;
        t.format = format;
        t.levels = d.MipLevels == 0 ? fullLineMipCount(d.Width) : int(d.MipLevels);
        t.desc.MipLevels = UINT(t.levels);
        if (d.Usage == D3D11_USAGE_STAGING)
            for (int sub = 0; sub < t.subresources(); ++sub) t.staging.emplace_back(t.rowBytes(sub % t.levels), 0);
        else
            t.texels = std::make_unique<fxport::Texture1D>(core(), int(d.Width), int(d.ArraySize), t.levels, format, d.ArraySize > 1);
        if (pInitialData)
            if (HRESULT hr = fillLines(t, pInitialData); FAILED(hr)) return hr;
        *ppTexture1D = texture.release();
        return succeed();
    });
}

HRESULT lineShaderResourceView(Device* device, LineTexture* t, const D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc, ID3D11ShaderResourceView** pp) {
    const char* call = "CreateShaderResourceView";
    if (!(t->desc.BindFlags & D3D11_BIND_SHADER_RESOURCE))
        return fail(E_INVALIDARG, std::string(call) + ": the texture's BindFlags = " + std::to_string(t->desc.BindFlags) + " lack D3D11_BIND_SHADER_RESOURCE");
    D3D11_SHADER_RESOURCE_VIEW_DESC d = defaultLineView(*t);
    if (!pDesc && depthFamilyOf(t->desc.Format))
        return fail(E_INVALIDARG, std::string(call) + ": pDesc is null for a " + formatName(t->desc.Format) + " texture (a typeless texture's view names its Format)");
    if (pDesc)
        if (HRESULT hr = checkLineSrv(*t, *pDesc, d); FAILED(hr)) return hr;
    if (pDesc && pDesc->Format != DXGI_FORMAT_UNKNOWN) d.Format = pDesc->Format;
    if (!pp) return succeed();
    return guarded(call, [&] {
        auto view = std::unique_ptr<ShaderResourceView, void (*)(ShaderResourceView*)>(new ShaderResourceView(device, t, d),
                                                                                       [](ShaderResourceView* v) { v->Release(); });
        const bool array = d.ViewDimension == D3D11_SRV_DIMENSION_TEXTURE1DARRAY;
        const UINT first = array ? d.Texture1DArray.MostDetailedMip : d.Texture1D.MostDetailedMip;
        const UINT levels = array ? d.Texture1DArray.MipLevels : d.Texture1D.MipLevels;
        const UINT slice = array ? d.Texture1DArray.FirstArraySlice : 0, slices = array ? d.Texture1DArray.ArraySize : 1;
        // The texture itself when the view sees all of it as its own dimension; a GL view otherwise.
        if (first != 0 || levels != UINT(t->levels) || slices != t->desc.ArraySize || array != t->texels->isArray())
            view->lineRange = std::make_unique<fxport::Texture1D>(*t->texels, int(first), int(levels), int(slice), int(slices), array);
        *pp = view.release();
        return succeed();
    });
}

HRESULT lineUnorderedAccessView(Device* device, LineTexture* t, const D3D11_UNORDERED_ACCESS_VIEW_DESC* pDesc, ID3D11UnorderedAccessView** pp) {
    const std::string call = "CreateUnorderedAccessView", at = call + ": D3D11_UNORDERED_ACCESS_VIEW_DESC.";
    D3D11_UNORDERED_ACCESS_VIEW_DESC d;
    d.Format = t->desc.Format;
    d.ViewDimension = t->desc.ArraySize > 1 ? D3D11_UAV_DIMENSION_TEXTURE1DARRAY : D3D11_UAV_DIMENSION_TEXTURE1D;
    d.Texture1DArray = {0, 0, t->desc.ArraySize};
    if (pDesc) {
        const bool oneD = pDesc->ViewDimension == D3D11_UAV_DIMENSION_TEXTURE1D, array = pDesc->ViewDimension == D3D11_UAV_DIMENSION_TEXTURE1DARRAY;
        if (!oneD && !array)
            return fail(E_INVALIDARG, at + "ViewDimension = " + std::to_string(pDesc->ViewDimension) + " for a 1D texture (D3D11_UAV_DIMENSION_TEXTURE1D or TEXTURE1DARRAY)");
        if (oneD && t->desc.ArraySize > 1) return fail(E_INVALIDARG, at + "ViewDimension = D3D11_UAV_DIMENSION_TEXTURE1D for an array (TEXTURE1DARRAY)");
        if (HRESULT hr = checkLineViewFormat(at, pDesc->Format, *t); FAILED(hr)) return hr;
        d.ViewDimension = pDesc->ViewDimension;
        d.Texture1D = pDesc->Texture1D;
        d.Texture1DArray = array ? pDesc->Texture1DArray : D3D11_TEX1D_ARRAY_UAV{pDesc->Texture1D.MipSlice, 0, 1};
    }
    const auto& a = d.Texture1DArray;
    if (a.MipSlice >= UINT(t->levels))
        return fail(E_INVALIDARG, at + "MipSlice = " + std::to_string(a.MipSlice) + " (the texture has " + std::to_string(t->levels) + " levels)");
    if (HRESULT hr = checkViewSlices(at + "Texture1DArray.", a.FirstArraySlice, a.ArraySize, t->desc.ArraySize); FAILED(hr)) return hr;
    if (!pp) return succeed();
    return guarded(call.c_str(), [&] {
        auto view = std::unique_ptr<UnorderedAccessView, void (*)(UnorderedAccessView*)>(new UnorderedAccessView(device, t, nullptr, nullptr, d),
                                                                                         [](UnorderedAccessView* v) { v->Release(); });
        // The shader writes level 0 of what is bound: a view starting at MipSlice, of the view's slices.
        view->image = std::make_unique<fxport::Texture1D>(*t->texels, int(a.MipSlice), 1, int(a.FirstArraySlice), int(a.ArraySize),
                                                          d.ViewDimension == D3D11_UAV_DIMENSION_TEXTURE1DARRAY);
        *pp = view.release();
        return succeed();
    });
}

}  // namespace fxport::d3d11
