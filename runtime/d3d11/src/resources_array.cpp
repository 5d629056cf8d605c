// Array textures: CreateTexture2D with ArraySize > 1 (and cube arrays: TEXTURECUBE with 6N), a device-core
// Texture2DArray (or CPU memory for USAGE_STAGING), and their views. A shader-resource view sees
// any range of levels and slices (a part through a texture view sharing the texels); a
// render-target or depth-stencil view is one slice of one level (a cascaded shadow map: a
// typeless depth array drawn slice by slice, sampled as a whole) or a layered view of several,
// drawn into through SV_RenderTargetArrayIndex. D3D numbers subresources level + slice *
// MipLevels, which pInitialData follows. Multisampled arrays (Texture2DMSArray) are made here, their
// views in resources_multisample_array.cpp. Not here yet: unordered-access arrays. A cube array's TEXTURECUBEARRAY view is a GL cube map array view of
// its layers.
#include <cstring>

#include "d3d11_impl.h"
#include "device/array_format_view.h"
#include "device/cube_view.h"
#include "device/multisample_target.h"
#include "device/target_view.h"
#include "guarded.h"

namespace fxport::d3d11 {

namespace {

constexpr UINT kMaxSlices = 2048;  // D3D11_REQ_TEXTURE2D_ARRAY_AXIS_DIMENSION

// What fxport's arrays are not yet, each E_NOTIMPL naming the field; a multisampled array
// (Texture2DMSArray) has the rules of a multisampled texture.
HRESULT checkArrayScope(const D3D11_TEXTURE2D_DESC& d, const std::string& at, bool hasData) {
    if (d.SampleDesc.Count > 1) return checkMultisampleDesc(d, hasData);
    if (d.BindFlags & D3D11_BIND_UNORDERED_ACCESS)
        return fail(E_NOTIMPL, at + "BindFlags = " + std::to_string(d.BindFlags) + " with ArraySize = " + std::to_string(d.ArraySize) +
                                   ": fxport's array textures are SHADER_RESOURCE, RENDER_TARGET and DEPTH_STENCIL only (no UAV arrays yet)");
    if (d.BindFlags & ~UINT(D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_RENDER_TARGET | D3D11_BIND_DEPTH_STENCIL))
        return fail(E_NOTIMPL, at + "BindFlags = " + std::to_string(d.BindFlags) + ": only SHADER_RESOURCE, RENDER_TARGET and DEPTH_STENCIL for an array texture");
    if (d.MiscFlags & ~UINT(D3D11_RESOURCE_MISC_GENERATE_MIPS | D3D11_RESOURCE_MISC_TEXTURECUBE))
        return fail(E_NOTIMPL, at + "MiscFlags = " + std::to_string(d.MiscFlags) + ": an array texture takes D3D11_RESOURCE_MISC_GENERATE_MIPS and TEXTURECUBE only");
    if ((d.MiscFlags & D3D11_RESOURCE_MISC_TEXTURECUBE) && (d.ArraySize % 6 != 0 || d.Width != d.Height))
        return fail(E_INVALIDARG, at + "ArraySize = " + std::to_string(d.ArraySize) + ", Width x Height = " + std::to_string(d.Width) + " x " +
                                      std::to_string(d.Height) + " with D3D11_RESOURCE_MISC_TEXTURECUBE (a cube array is square, 6 faces a cube)");
    return S_OK;
}

// The texels' format: a colour format, or a depth array's (a typeless depth family, sampled and
// drawn into; or a depth format, drawn into only), whose slices a depth-stencil view draws into.
HRESULT arrayFormat(const D3D11_TEXTURE2D_DESC& d, bool hasData, SurfaceFormat& format) {
    const std::string at = "CreateTexture2D: D3D11_TEXTURE2D_DESC.";
    const bool depthTarget = (d.BindFlags & D3D11_BIND_DEPTH_STENCIL) != 0;
    const DepthFamily* family = depthFamilyOf(d.Format);
    if (!family && depthTarget) family = depthFamilyOfView(d.Format);
    if (depthTarget && (d.BindFlags & D3D11_BIND_RENDER_TARGET))
        return fail(E_INVALIDARG, at + "BindFlags = " + std::to_string(d.BindFlags) + ": a texture is a depth-stencil or a render target, not both");
    if (family && (d.BindFlags & D3D11_BIND_RENDER_TARGET))
        return fail(E_NOTIMPL, at + "BindFlags = " + std::to_string(d.BindFlags) + " with Format = " + formatName(d.Format) +
                                   ": fxport keeps a typeless texture as a depth texture (DEPTH_STENCIL and SHADER_RESOURCE only)");
    if (depthTarget && (d.BindFlags & D3D11_BIND_SHADER_RESOURCE) && family && family->typeless != d.Format)
        return fail(E_INVALIDARG, at + "BindFlags = " + std::to_string(d.BindFlags) + " with Format = " + formatName(d.Format) +
                                      ": a depth texture a shader samples is made typeless (R32_TYPELESS, R24G8_TYPELESS, R16_TYPELESS)");
    if (depthTarget && (d.MiscFlags & D3D11_RESOURCE_MISC_GENERATE_MIPS))
        return fail(E_INVALIDARG, at + "MiscFlags = D3D11_RESOURCE_MISC_GENERATE_MIPS with BIND_DEPTH_STENCIL (mips are generated for render targets)");
    if (family && hasStencil(family->depth) && hasData)
        return fail(E_NOTIMPL, at + "Format = " + formatName(d.Format) + " with pInitialData: fxport does not upload packed depth-stencil texels");
    if (depthTarget && hasData) return fail(E_INVALIDARG, at + "BindFlags has DEPTH_STENCIL and pInitialData is given");
    if (family) {
        format = family->sampled;
        return S_OK;
    }
    if (textureFormat(d.Format, format) || typelessColourStorage(d.Format, format)) return checkCompressedUse(at, d, format);
    return fail(d.Format == DXGI_FORMAT_UNKNOWN ? E_INVALIDARG : E_NOTIMPL,
                at + "Format = " + formatName(d.Format) + " (" + std::to_string(d.Format) + "): not an array texture format fxport supports (docs/API.md lists them)");
}

// D3D's own rules for an array description.
HRESULT checkArrayDesc(const D3D11_TEXTURE2D_DESC& d, bool hasData, SurfaceFormat& format) {
    const std::string at = "CreateTexture2D: D3D11_TEXTURE2D_DESC.";
    if (d.ArraySize > kMaxSlices) return fail(E_INVALIDARG, at + "ArraySize = " + std::to_string(d.ArraySize) + " (1 to 2048)");
    if (d.SampleDesc.Count == 0) return fail(E_INVALIDARG, at + "SampleDesc.Count = 0");
    if (HRESULT hr = checkArrayScope(d, at, hasData); FAILED(hr)) return hr;
    const int full = fullMipCount(d.Width, d.Height);
    if (int(d.MipLevels) > full)
        return fail(E_INVALIDARG, at + "MipLevels = " + std::to_string(d.MipLevels) + " (a " + std::to_string(d.Width) + "x" + std::to_string(d.Height) +
                                      " texture has at most " + std::to_string(full) + ")");
    // D3D11: a dynamic texture is one level of one slice.
    if (d.Usage == D3D11_USAGE_DYNAMIC)
        return fail(E_INVALIDARG, at + "Usage = D3D11_USAGE_DYNAMIC with ArraySize = " + std::to_string(d.ArraySize) + " (a dynamic texture has ArraySize 1)");
    if (HRESULT hr = checkUsage("CreateTexture2D", "D3D11_TEXTURE2D_DESC", d.Usage, d.BindFlags, d.CPUAccessFlags, hasData); FAILED(hr)) return hr;
    if (HRESULT hr = arrayFormat(d, hasData, format); FAILED(hr)) return hr;
    if ((d.MiscFlags & D3D11_RESOURCE_MISC_GENERATE_MIPS) && isIntegerFormat(format))
        return fail(E_INVALIDARG, at + "MiscFlags = D3D11_RESOURCE_MISC_GENERATE_MIPS with Format = " + formatName(d.Format) +
                                      ": integer texels cannot be filtered into smaller levels");
    return S_OK;
}

// Subresource `sub` of `initial`, packed tightly.
HRESULT packSubresource(const Texture& t, const D3D11_SUBRESOURCE_DATA& s, UINT sub, Subresource at, std::vector<std::uint8_t>& packed) {
    const std::string where = "CreateTexture2D: pInitialData[" + std::to_string(sub) + "].";
    if (!s.pSysMem) return fail(E_INVALIDARG, where + "pSysMem is null");
    const std::size_t row = rowBytes(t.format, t.levelWidth(at.level));  // of 4x4 blocks for BC formats
    if (s.SysMemPitch < row)
        return fail(E_INVALIDARG, where + "SysMemPitch = " + std::to_string(s.SysMemPitch) + ", less than a row (" + std::to_string(row) + " bytes)");
    packed.resize(t.levelBytes(at.level));
    for (int y = 0; y < rowCount(t.format, t.levelHeight(at.level)); ++y)
        std::memcpy(&packed[std::size_t(y) * row], static_cast<const std::uint8_t*>(s.pSysMem) + std::size_t(y) * s.SysMemPitch, row);
    return S_OK;
}

HRESULT fillArray(Texture& t, const D3D11_SUBRESOURCE_DATA* initial) {
    std::vector<std::uint8_t> packed;
    for (UINT sub = 0; sub < UINT(t.subresources()); ++sub) {
        Subresource at;
        splitSubresource(t, sub, at);
        if (HRESULT hr = packSubresource(t, initial[sub], sub, at, packed); FAILED(hr)) return hr;
        writeSubresource(t, at, nullptr, packed);
    }
    return S_OK;
}

}  // namespace

HRESULT checkSlices(const std::string& at, UINT first, UINT count, int slices) {
    if (count == 0 || first >= UINT(slices) || count > UINT(slices) - first)
        return fail(E_INVALIDARG, at + "FirstArraySlice + ArraySize = " + std::to_string(first) + " + " + std::to_string(count) + " (the texture has " +
                                      std::to_string(slices) + " slices)");
    return S_OK;
}

HRESULT createTextureArray(Device* device, const D3D11_TEXTURE2D_DESC& d, const D3D11_SUBRESOURCE_DATA* pInitialData, ID3D11Texture2D** pp) {
    SurfaceFormat format = SurfaceFormat::Color;
    if (HRESULT hr = checkArrayDesc(d, pInitialData && pInitialData->pSysMem, format); FAILED(hr)) return hr;
    if (!pp) return succeed();  // D3D: validation only
    return guarded("CreateTexture2D", [&] {
        auto texture = std::unique_ptr<Texture, void (*)(Texture*)>(new Texture(device, d), [](Texture* t) { t->Release(); });
        Texture& t = *texture;
        t.format = format;
        t.levels = d.MipLevels == 0 ? fullMipCount(d.Width, d.Height) : int(d.MipLevels);
        t.desc.MipLevels = UINT(t.levels);
        if (d.Usage == D3D11_USAGE_STAGING)
            for (int sub = 0; sub < t.subresources(); ++sub) t.staging.emplace_back(t.levelBytes(sub % t.levels), 0);
        else if (d.SampleDesc.Count > 1)
            t.array = std::make_unique<core::MultisampleArray>(device->core(), int(d.Width), int(d.Height), int(d.ArraySize), format,
                                                               int(d.SampleDesc.Count));
        else
            t.array = std::make_unique<fxport::Texture2DArray>(device->core(), int(d.Width), int(d.Height), int(d.ArraySize), t.levels, format);
        if (pInitialData)
            if (HRESULT hr = fillArray(t, pInitialData); FAILED(hr)) return hr;
        *pp = texture.release();
        return succeed();
    });
}

namespace {

bool isCubeArray(const Texture& t) { return (t.desc.MiscFlags & D3D11_RESOURCE_MISC_TEXTURECUBE) != 0; }

// A TEXTURECUBEARRAY view of a cube array: NumCubes cubes from face First2DArrayFace.
HRESULT cubeArrayShaderResourceView(Device* device, Texture* t, const D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc, ID3D11ShaderResourceView** pp) {
    const std::string call = "CreateShaderResourceView", at = call + ": D3D11_SHADER_RESOURCE_VIEW_DESC.";
    D3D11_SHADER_RESOURCE_VIEW_DESC d;
    d.Format = t->desc.Format;
    d.ViewDimension = D3D11_SRV_DIMENSION_TEXTURECUBEARRAY;
    d.TextureCubeArray = {0, UINT(t->levels), 0, UINT(t->slices() / 6)};
    if (pDesc) {
        if (HRESULT f = checkViewFormat(call.c_str(), "D3D11_SHADER_RESOURCE_VIEW_DESC", pDesc->Format, *t, false); FAILED(f)) return f;
        const auto& c = pDesc->TextureCubeArray;
        const UINT levels = c.MipLevels == UINT(-1) && c.MostDetailedMip < UINT(t->levels) ? UINT(t->levels) - c.MostDetailedMip : c.MipLevels;
        if (c.MostDetailedMip >= UINT(t->levels) || levels == 0 || levels > UINT(t->levels) - c.MostDetailedMip)
            return fail(E_INVALIDARG, at + "TextureCubeArray = {MostDetailedMip " + std::to_string(c.MostDetailedMip) + ", MipLevels " +
                                          std::to_string(c.MipLevels) + "} (the texture has " + std::to_string(t->levels) + " levels)");
        if (c.NumCubes == 0 || c.First2DArrayFace >= UINT(t->slices()) || c.NumCubes > (UINT(t->slices()) - c.First2DArrayFace) / 6)
            return fail(E_INVALIDARG, at + "TextureCubeArray = {First2DArrayFace " + std::to_string(c.First2DArrayFace) + ", NumCubes " +
                                          std::to_string(c.NumCubes) + "} (the texture has " + std::to_string(t->slices()) + " faces)");
        d.TextureCubeArray = {c.MostDetailedMip, levels, c.First2DArrayFace, c.NumCubes};
        if (pDesc->Format != DXGI_FORMAT_UNKNOWN) d.Format = pDesc->Format;
    }
    if (!pp) return succeed();
    return guarded(call.c_str(), [&] {
        auto view = std::unique_ptr<ShaderResourceView, void (*)(ShaderResourceView*)>(new ShaderResourceView(device, t, d),
                                                                                       [](ShaderResourceView* v) { v->Release(); });
        const auto& c = d.TextureCubeArray;
        const fxport::Texture2DArray::Cubes cubes{int(c.First2DArrayFace), int(c.NumCubes)};
        if (const SurfaceFormat read = viewSurface(d.Format, *t); read != t->format)  // a typeless cube array read as another member
            view->arrayRange = std::make_unique<core::ArrayFormatView>(*t->array, int(c.MostDetailedMip), int(c.MipLevels), cubes, read);
        else
            view->arrayRange = std::make_unique<fxport::Texture2DArray>(*t->array, int(c.MostDetailedMip), int(c.MipLevels), cubes);
        *pp = view.release();
        return succeed();
    });
}

// A TEXTURECUBE view of a cube array: its first cube (D3D11_TEX_CUBE_SRV names levels only; another
// cube is a TEXTURECUBEARRAY view of one cube), read by TextureCube through a GL cube map view.
HRESULT firstCubeShaderResourceView(Device* device, Texture* t, const D3D11_SHADER_RESOURCE_VIEW_DESC& desc, ID3D11ShaderResourceView** pp) {
    const std::string call = "CreateShaderResourceView", at = call + ": D3D11_SHADER_RESOURCE_VIEW_DESC.";
    if (HRESULT f = checkViewFormat(call.c_str(), "D3D11_SHADER_RESOURCE_VIEW_DESC", desc.Format, *t, false); FAILED(f)) return f;
    const auto& c = desc.TextureCube;
    const UINT levels = c.MipLevels == UINT(-1) && c.MostDetailedMip < UINT(t->levels) ? UINT(t->levels) - c.MostDetailedMip : c.MipLevels;
    if (c.MostDetailedMip >= UINT(t->levels) || levels == 0 || levels > UINT(t->levels) - c.MostDetailedMip)
        return fail(E_INVALIDARG, at + "TextureCube = {MostDetailedMip " + std::to_string(c.MostDetailedMip) + ", MipLevels " +
                                      std::to_string(c.MipLevels) + "} (the texture has " + std::to_string(t->levels) + " levels)");
    D3D11_SHADER_RESOURCE_VIEW_DESC d = desc;
    d.TextureCube = {c.MostDetailedMip, levels};
    if (d.Format == DXGI_FORMAT_UNKNOWN) d.Format = t->desc.Format;
    if (!pp) return succeed();
    return guarded(call.c_str(), [&] {
        auto view = std::unique_ptr<ShaderResourceView, void (*)(ShaderResourceView*)>(new ShaderResourceView(device, t, d),
                                                                                       [](ShaderResourceView* v) { v->Release(); });
        view->cubeRange = std::make_unique<core::CubeView>(*t->array, int(c.MostDetailedMip), int(levels), 0, viewSurface(d.Format, *t));
        *pp = view.release();
        return succeed();
    });
}

}  // namespace

HRESULT arrayShaderResourceView(Device* device, Texture* t, const D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc, ID3D11ShaderResourceView** pp) {
    const std::string call = "CreateShaderResourceView", at = call + ": D3D11_SHADER_RESOURCE_VIEW_DESC.";
    if (t->desc.SampleDesc.Count > 1) return multisampleArrayShaderResourceView(device, t, pDesc, pp);
    // A cube array is viewed as cubes by default (D3D's view of the whole resource), or as 2D slices.
    if (isCubeArray(*t) && (!pDesc || pDesc->ViewDimension == D3D11_SRV_DIMENSION_TEXTURECUBEARRAY))
        return cubeArrayShaderResourceView(device, t, pDesc, pp);
    if (isCubeArray(*t) && pDesc->ViewDimension == D3D11_SRV_DIMENSION_TEXTURECUBE) return firstCubeShaderResourceView(device, t, *pDesc, pp);
    D3D11_SHADER_RESOURCE_VIEW_DESC d;
    d.Format = t->desc.Format;
    d.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2DARRAY;
    d.Texture2DArray = {0, UINT(t->levels), 0, UINT(t->slices())};
    if (pDesc) {
        if (pDesc->ViewDimension != D3D11_SRV_DIMENSION_TEXTURE2DARRAY)
            return fail(pDesc->ViewDimension == D3D11_SRV_DIMENSION_UNKNOWN ? E_INVALIDARG : E_NOTIMPL,
                        at + "ViewDimension = " + std::to_string(pDesc->ViewDimension) + " (fxport views an array texture as D3D11_SRV_DIMENSION_TEXTURE2DARRAY" +
                            (isCubeArray(*t) ? std::string(", a cube array also as TEXTURECUBEARRAY or TEXTURECUBE)") : std::string(")")));
        if (HRESULT f = checkViewFormat(call.c_str(), "D3D11_SHADER_RESOURCE_VIEW_DESC", pDesc->Format, *t, false); FAILED(f)) return f;
        if (depthFamilyOf(t->desc.Format) && viewSurface(pDesc->Format, *t) != t->format)
            return fail(E_NOTIMPL, at + "Format = " + formatName(pDesc->Format) + " of a " + formatName(t->desc.Format) +
                                       " array: no stencil view of a depth array yet");
        const auto& a = pDesc->Texture2DArray;
        if (a.MostDetailedMip >= UINT(t->levels))
            return fail(E_INVALIDARG, at + "Texture2DArray.MostDetailedMip = " + std::to_string(a.MostDetailedMip) + " (the texture has " +
                                          std::to_string(t->levels) + " levels)");
        const UINT levels = a.MipLevels == UINT(-1) ? UINT(t->levels) - a.MostDetailedMip : a.MipLevels;
        if (levels == 0 || levels > UINT(t->levels) - a.MostDetailedMip)
            return fail(E_INVALIDARG, at + "Texture2DArray.MipLevels = " + std::to_string(a.MipLevels) + " from MostDetailedMip " +
                                          std::to_string(a.MostDetailedMip) + " (the texture has " + std::to_string(t->levels) + " levels)");
        if (HRESULT f = checkSlices(at + "Texture2DArray.", a.FirstArraySlice, a.ArraySize, t->slices()); FAILED(f)) return f;
        d.Texture2DArray = {a.MostDetailedMip, levels, a.FirstArraySlice, a.ArraySize};
        if (pDesc->Format != DXGI_FORMAT_UNKNOWN) d.Format = pDesc->Format;
    }
    if (!pp) return succeed();
    return guarded(call.c_str(), [&] {
        auto view = std::unique_ptr<ShaderResourceView, void (*)(ShaderResourceView*)>(new ShaderResourceView(device, t, d),
                                                                                       [](ShaderResourceView* v) { v->Release(); });
        const auto& a = d.Texture2DArray;
        if (const SurfaceFormat read = viewSurface(d.Format, *t); read != t->format)  // a typeless array read as another member
            view->arrayRange = std::make_unique<core::ArrayFormatView>(*t->array, int(a.MostDetailedMip), int(a.MipLevels), int(a.FirstArraySlice),
                                                                       int(a.ArraySize), read);
        else if (a.MostDetailedMip != 0 || a.MipLevels != UINT(t->levels) || a.FirstArraySlice != 0 || a.ArraySize != UINT(t->slices()))
            view->arrayRange = std::make_unique<fxport::Texture2DArray>(*t->array, int(a.MostDetailedMip), int(a.MipLevels), int(a.FirstArraySlice),
                                                                        int(a.ArraySize));
        *pp = view.release();
        return succeed();
    });
}

HRESULT arrayRenderTargetView(Device* device, Texture* t, const D3D11_RENDER_TARGET_VIEW_DESC* pDesc, ID3D11RenderTargetView** pp) {
    if (t->desc.SampleDesc.Count > 1) return multisampleArrayRenderTargetView(device, t, pDesc, pp);
    const std::string call = "CreateRenderTargetView", at = call + ": D3D11_RENDER_TARGET_VIEW_DESC.";
    D3D11_RENDER_TARGET_VIEW_DESC d;
    d.Format = t->desc.Format;
    d.ViewDimension = D3D11_RTV_DIMENSION_TEXTURE2DARRAY;
    d.Texture2DArray = {0, 0, UINT(t->slices())};
    if (pDesc) {
        if (pDesc->ViewDimension != D3D11_RTV_DIMENSION_TEXTURE2DARRAY)
            return fail(pDesc->ViewDimension == D3D11_RTV_DIMENSION_UNKNOWN ? E_INVALIDARG : E_NOTIMPL,
                        at + "ViewDimension = " + std::to_string(pDesc->ViewDimension) + " (fxport views an array texture as D3D11_RTV_DIMENSION_TEXTURE2DARRAY)");
        if (HRESULT f = checkViewFormat(call.c_str(), "D3D11_RENDER_TARGET_VIEW_DESC", pDesc->Format, *t, false); FAILED(f)) return f;
        d = *pDesc;
        if (d.Format == DXGI_FORMAT_UNKNOWN) d.Format = t->desc.Format;
    }
    const auto& a = d.Texture2DArray;
    if (a.MipSlice >= UINT(t->levels))
        return fail(E_INVALIDARG, at + "Texture2DArray.MipSlice = " + std::to_string(a.MipSlice) + " (the texture has " + std::to_string(t->levels) + " levels)");
    if (HRESULT f = checkSlices(at + "Texture2DArray.", a.FirstArraySlice, a.ArraySize, t->slices()); FAILED(f)) return f;
    if (!pp) return succeed();
    return guarded(call.c_str(), [&] {
        auto view = std::unique_ptr<RenderTargetView, void (*)(RenderTargetView*)>(new RenderTargetView(device, t, d),
                                                                                   [](RenderTargetView* v) { v->Release(); });
        // Several slices: a layered target, each primitive in the slice its SV_RenderTargetArrayIndex names.
        if (const SurfaceFormat written = viewSurface(d.Format, *t); written != t->format)  // a typeless array in another member
            view->slice = std::make_unique<core::TargetView>(*t->array, int(a.FirstArraySlice), int(a.MipSlice), int(a.ArraySize), written);
        else
            view->slice = std::make_unique<RenderTarget2D>(*t->array, int(a.FirstArraySlice), int(a.MipSlice), int(a.ArraySize));
        *pp = view.release();
        return succeed();
    });
}


HRESULT arrayDepthStencilView(Device* device, Texture* t, const D3D11_DEPTH_STENCIL_VIEW_DESC* pDesc, ID3D11DepthStencilView** pp) {
    const std::string call = "CreateDepthStencilView", at = call + ": D3D11_DEPTH_STENCIL_VIEW_DESC.";
    D3D11_DEPTH_STENCIL_VIEW_DESC d;
    d.Format = t->desc.Format;
    d.ViewDimension = D3D11_DSV_DIMENSION_TEXTURE2DARRAY;
    d.Texture2DArray = {0, 0, UINT(t->slices())};
    if (pDesc) {
        if (pDesc->ViewDimension != D3D11_DSV_DIMENSION_TEXTURE2DARRAY)
            return fail(pDesc->ViewDimension == D3D11_DSV_DIMENSION_UNKNOWN ? E_INVALIDARG : E_NOTIMPL,
                        at + "ViewDimension = " + std::to_string(pDesc->ViewDimension) + " (fxport views an array texture as D3D11_DSV_DIMENSION_TEXTURE2DARRAY)");
        if (HRESULT f = checkViewFormat(call.c_str(), "D3D11_DEPTH_STENCIL_VIEW_DESC", pDesc->Format, *t, true); FAILED(f)) return f;
        if (HRESULT f = checkDepthViewFlags(at, pDesc->Flags, pDesc->Format != DXGI_FORMAT_UNKNOWN ? pDesc->Format : t->desc.Format); FAILED(f))
            return f;
        d = *pDesc;
        if (d.Format == DXGI_FORMAT_UNKNOWN) d.Format = t->desc.Format;
    }
    const auto& a = d.Texture2DArray;
    if (a.MipSlice >= UINT(t->levels))
        return fail(E_INVALIDARG, at + "Texture2DArray.MipSlice = " + std::to_string(a.MipSlice) + " (the texture has " + std::to_string(t->levels) + " levels)");
    if (HRESULT f = checkSlices(at + "Texture2DArray.", a.FirstArraySlice, a.ArraySize, t->slices()); FAILED(f)) return f;
    if (!pp) return succeed();
    return guarded(call.c_str(), [&] {
        auto view = std::unique_ptr<DepthStencilView, void (*)(DepthStencilView*)>(new DepthStencilView(device, t, d),
                                                                                   [](DepthStencilView* v) { v->Release(); });
        view->sliceTexture = std::make_unique<fxport::Texture2D>(*t->array, int(a.FirstArraySlice), int(a.MipSlice), int(a.ArraySize));
        view->slice = std::make_unique<core::DepthBuffer>(device->core(), *view->sliceTexture);
        *pp = view.release();
        return succeed();
    });
}

}  // namespace fxport::d3d11
