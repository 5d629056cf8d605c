// Shader-resource, render-target and depth-stencil views of 2D textures (the whole texture: one
// format, all levels for SRVs, level 0 for RTVs and DSVs; TEXTURE2DMS views of multisampled ones;
// array textures' views in resources_array.cpp); shader-resource and unordered-access
// views of elements of typed (Buffer<T>), structured (StructuredBuffer<T>) and raw
// (ByteAddressBuffer) buffers, and
// unordered-access views of level 0 of a 2D texture (RWTexture2D).
#include <optional>

#include "d3d11_impl.h"
#include "device/cube_view.h"
#include "device/target_view.h"
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
        hr = fail(E_NOTIMPL, std::string(call) + ": views of buffers are shader-resource and unordered-access views only");
        return nullptr;
    }
    auto* t = dynamic_cast<Texture*>(resource);
    if (!t || &t->device() != device) {
        hr = fail(E_INVALIDARG, std::string(call) + ": pResource was not made by this device");
        return nullptr;
    }
    return t;
}

// A typeless texture is viewed only through a description naming the view's format.
HRESULT needsDescription(const char* call, const Texture& t, bool given) {
    SurfaceFormat stored;
    if (given || (!depthFamilyOf(t.desc.Format) && !typelessColourStorage(t.desc.Format, stored))) return S_OK;
    return fail(E_INVALIDARG, std::string(call) + ": pDesc is null for a " + formatName(t.desc.Format) + " texture (a typeless texture's view names its Format)");
}

// Render-target and unordered-access views of a typeless colour texture in another member of its
// family write through a GL texture view of level 0 (a multisampled one: in its stored format only).
HRESULT checkStoredFormat(const char* call, const char* desc, DXGI_FORMAT viewFormat, const Texture& t) {
    if (viewSurface(viewFormat, t) == t.format || (t.colour && t.desc.SampleDesc.Count == 1)) return S_OK;
    return fail(E_NOTIMPL, std::string(call) + ": " + desc + ".Format = " + formatName(viewFormat) + " of a multisampled " + formatName(t.desc.Format) +
                               " texture: fxport writes it in the format it stores (" + surfaceFormatName(t.format) + ")");
}

// FirstElement's byte offset must be a multiple of the GL's alignment for a view of part of a
// buffer (16 bytes on common drivers); D3D has no such rule, so any other is E_NOTIMPL.
HRESULT checkAlignment(Device& device, const std::string& at, UINT first, std::size_t offset, bool storage) {
    const std::size_t alignment = core::bufferOffsetAlignment(device.core(), storage);
    if (offset % alignment == 0) return S_OK;
    return fail(E_NOTIMPL, at + ".FirstElement = " + std::to_string(first) + ": the view starts at byte " + std::to_string(offset) +
                               ", and fxport's GL starts " + (storage ? "a storage buffer range" : "a buffer texture") + " at multiples of " +
                               std::to_string(alignment) + " bytes only");
}

// The buffer view's elements [first, first + count): of a structured buffer (StructureByteStride
// bytes each) or a raw one (R32_TYPELESS with the RAW flag: 4-byte elements), bound as the byte
// range `range`. `desc` names the description for messages ("D3D11_SHADER_RESOURCE_VIEW_DESC.Buffer").
// A typed view (Buffer<T> / RWBuffer<T>: neither structured nor raw) reads elements of `format`:
// its SurfaceFormat goes to `typed`.
HRESULT checkBufferView(const char* call, const std::string& desc, const Buffer& b, DXGI_FORMAT format, bool raw, UINT first, UINT count,
                        std::optional<SurfaceFormat>& typed, BufferRange& range) {
    const std::string at = std::string(call) + ": " + desc;
    const bool structured = (b.desc.MiscFlags & D3D11_RESOURCE_MISC_BUFFER_STRUCTURED) != 0;
    if (!raw && !structured) {
        SurfaceFormat f = SurfaceFormat::Color;
        if (format == DXGI_FORMAT_UNKNOWN) return fail(E_INVALIDARG, std::string(call) + ": Format = DXGI_FORMAT_UNKNOWN for a typed buffer view (Buffer<T> needs the element format)");
        if (!textureFormat(format, f) || !core::isTexelBufferFormat(f))
            return fail(E_NOTIMPL, std::string(call) + ": Format = " + formatName(format) + " (" + std::to_string(format) + "): not a typed-buffer format fxport supports");
        const UINT elements = b.desc.ByteWidth / UINT(bytesPerPixel(f));
        if (first >= elements || count == 0 || count > elements - first)
            return fail(E_INVALIDARG, at + " = {FirstElement " + std::to_string(first) + ", NumElements " + std::to_string(count) + "}: the buffer holds " +
                                          std::to_string(elements) + " elements of " + formatName(format));
        if (HRESULT hr = checkAlignment(b.device(), at, first, std::size_t(first) * std::size_t(bytesPerPixel(f)), false); FAILED(hr)) return hr;
        typed = f;
        range = BufferRange{first, count};
        return S_OK;
    }
    if (raw) {
        if (!(b.desc.MiscFlags & D3D11_RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS))
            return fail(E_INVALIDARG, at + " asks for a raw view of a buffer made without D3D11_RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS");
        if (format != DXGI_FORMAT_R32_TYPELESS)
            return fail(E_INVALIDARG, std::string(call) + ": Format = " + formatName(format) + " for a raw view (must be DXGI_FORMAT_R32_TYPELESS)");
    } else if (format != DXGI_FORMAT_UNKNOWN) {
        return fail(E_INVALIDARG, std::string(call) + ": Format = " + formatName(format) + " for a structured buffer (must be DXGI_FORMAT_UNKNOWN)");
    }
    const UINT stride = raw ? 4u : b.desc.StructureByteStride;
    const UINT elements = b.desc.ByteWidth / stride;
    if (first >= elements || count == 0 || count > elements - first)
        return fail(E_INVALIDARG, at + " = {FirstElement " + std::to_string(first) + ", NumElements " + std::to_string(count) + "}: the buffer has " +
                                      std::to_string(elements) + " elements");
    if (HRESULT hr = checkAlignment(b.device(), at, first, std::size_t(first) * stride, true); FAILED(hr)) return hr;
    range = BufferRange{first, count};
    // The whole buffer binds as it is (bytes 0); part of it as its byte range.
    if (first != 0 || count != elements) {
        range.offset = std::size_t(first) * stride;
        range.bytes = std::size_t(count) * stride;
    }
    return S_OK;
}

HRESULT bufferShaderResourceView(Device* device, Buffer* b, const D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc, ID3D11ShaderResourceView** pp) {
    const char* call = "CreateShaderResourceView";
    if (!(b->desc.BindFlags & D3D11_BIND_SHADER_RESOURCE))
        return fail(E_INVALIDARG, std::string(call) + ": the buffer's BindFlags = " + std::to_string(b->desc.BindFlags) + " lack D3D11_BIND_SHADER_RESOURCE");
    D3D11_SHADER_RESOURCE_VIEW_DESC d;
    d.ViewDimension = D3D11_SRV_DIMENSION_BUFFER;
    const bool structured = (b->desc.MiscFlags & D3D11_RESOURCE_MISC_BUFFER_STRUCTURED) != 0;
    d.Buffer.NumElements = structured ? b->desc.ByteWidth / b->desc.StructureByteStride : 0;
    if (!pDesc && !structured)
        return fail(E_INVALIDARG, std::string(call) + ": pDesc is null for a buffer that is not structured (a raw view needs a description)");
    std::optional<SurfaceFormat> typed;
    BufferRange range;
    if (pDesc) {
        d = *pDesc;
        HRESULT hr = S_OK;
        if (d.ViewDimension == D3D11_SRV_DIMENSION_BUFFER)
            hr = checkBufferView(call, "D3D11_SHADER_RESOURCE_VIEW_DESC.Buffer", *b, d.Format, false, d.Buffer.FirstElement, d.Buffer.NumElements, typed, range);
        else if (d.ViewDimension == D3D11_SRV_DIMENSION_BUFFEREX)
            hr = checkBufferView(call, "D3D11_SHADER_RESOURCE_VIEW_DESC.BufferEx", *b, d.Format, (d.BufferEx.Flags & D3D11_BUFFEREX_SRV_FLAG_RAW) != 0,
                                 d.BufferEx.FirstElement, d.BufferEx.NumElements, typed, range);
        else
            return fail(E_INVALIDARG, std::string(call) + ": D3D11_SHADER_RESOURCE_VIEW_DESC.ViewDimension = " + std::to_string(d.ViewDimension) +
                                          " for a buffer (D3D11_SRV_DIMENSION_BUFFER or BUFFEREX)");
        if (FAILED(hr)) return hr;
    }
    if (!pp) return succeed();
    return guarded(call, [&] {
        auto view = std::unique_ptr<ShaderResourceView, void (*)(ShaderResourceView*)>(new ShaderResourceView(device, b, d),
                                                                                       [](ShaderResourceView* v) { v->Release(); });
        view->range = range;
        if (typed) view->typed = std::make_unique<core::TexelBuffer>(device->core(), *b->gpu, *typed, std::size_t(range.count), std::size_t(range.first));
        *pp = view.release();
        return succeed();
    });
}

}  // namespace

HRESULT Device::CreateShaderResourceView(ID3D11Resource* pResource, const D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc,
                                         ID3D11ShaderResourceView** ppSRView) {
    const char* call = "CreateShaderResourceView";
    if (auto* b = dynamic_cast<Buffer*>(pResource); b && &b->device() == this) return bufferShaderResourceView(this, b, pDesc, ppSRView);
    if (auto* v = dynamic_cast<Volume*>(pResource); v && &v->device() == this) return volumeShaderResourceView(this, v, pDesc, ppSRView);
    if (auto* l = dynamic_cast<LineTexture*>(pResource); l && &l->device() == this) return lineShaderResourceView(this, l, pDesc, ppSRView);
    HRESULT hr;
    Texture* t = textureOf(this, pResource, call, hr);
    if (!t) return hr;
    if (!(t->desc.BindFlags & D3D11_BIND_SHADER_RESOURCE))
        return fail(E_INVALIDARG, std::string(call) + ": the texture's BindFlags = " + std::to_string(t->desc.BindFlags) +
                                      " lack D3D11_BIND_SHADER_RESOURCE");
    if (HRESULT f = needsDescription(call, *t, pDesc != nullptr); FAILED(f)) return f;
    if (t->slices() > 1) return arrayShaderResourceView(this, t, pDesc, ppSRView);
    // A cube texture is viewed as a cube (TEXTURECUBE), a multisampled one as TEXTURE2DMS, any other
    // as a 2D texture.
    const bool multisampled = t->desc.SampleDesc.Count > 1;
    const D3D11_SRV_DIMENSION dimension = t->cube ? D3D11_SRV_DIMENSION_TEXTURECUBE
                                          : multisampled ? D3D11_SRV_DIMENSION_TEXTURE2DMS
                                                         : D3D11_SRV_DIMENSION_TEXTURE2D;
    const char* const member = t->cube ? "TextureCube" : "Texture2D";
    D3D11_SHADER_RESOURCE_VIEW_DESC d;
    d.Format = t->desc.Format;
    d.ViewDimension = dimension;
    d.Texture2D.MipLevels = d.TextureCube.MipLevels = t->desc.MipLevels;
    if (pDesc) {
        if (pDesc->ViewDimension != dimension)
            return fail(pDesc->ViewDimension == D3D11_SRV_DIMENSION_UNKNOWN || multisampled || pDesc->ViewDimension == D3D11_SRV_DIMENSION_TEXTURE2DMS
                            ? E_INVALIDARG
                            : E_NOTIMPL,
                        std::string(call) + ": D3D11_SHADER_RESOURCE_VIEW_DESC.ViewDimension = " + std::to_string(pDesc->ViewDimension) +
                            " (fxport views this texture as D3D11_SRV_DIMENSION_" + (t->cube ? "TEXTURECUBE" : multisampled ? "TEXTURE2DMS" : "TEXTURE2D") + ")");
        if (HRESULT f = checkViewFormat(call, "D3D11_SHADER_RESOURCE_VIEW_DESC", pDesc->Format, *t, false); FAILED(f)) return f;
        const UINT first = t->cube ? pDesc->TextureCube.MostDetailedMip : pDesc->Texture2D.MostDetailedMip;
        const UINT levels = t->cube ? pDesc->TextureCube.MipLevels : pDesc->Texture2D.MipLevels;
        if (!multisampled && (first != 0 || (levels != UINT(-1) && levels != t->desc.MipLevels)))
            return fail(E_NOTIMPL, std::string(call) + ": D3D11_SHADER_RESOURCE_VIEW_DESC." + member + " = {MostDetailedMip " + std::to_string(first) +
                                       ", MipLevels " + std::to_string(levels) + "}: fxport views every level (0, -1)");
    }
    if (pDesc && pDesc->Format != DXGI_FORMAT_UNKNOWN) d.Format = pDesc->Format;
    const SurfaceFormat read = viewSurface(d.Format, *t);
    if (read != t->format && ((!t->colour && !t->cube) || multisampled))
        return fail(E_NOTIMPL, std::string(call) + ": D3D11_SHADER_RESOURCE_VIEW_DESC.Format = " + formatName(d.Format) + " of a " +
                                   formatName(t->desc.Format) + " " + (t->cube ? "cube" : "multisampled") +
                                   " texture: fxport reads those in their stored format only");
    if (!ppSRView) return succeed();
    return guarded(call, [&] {
        auto view = std::unique_ptr<ShaderResourceView, void (*)(ShaderResourceView*)>(new ShaderResourceView(this, t, d),
                                                                                       [](ShaderResourceView* v) { v->Release(); });
        if (read != t->format && t->cube) view->cubeRange = std::make_unique<core::CubeView>(*t->cube, read);  // GL texture views
        else if (read != t->format) view->formatView = std::make_unique<fxport::Texture2D>(*t->colour, read);
        *ppSRView = view.release();
        return succeed();
    });
}

HRESULT Device::CreateRenderTargetView(ID3D11Resource* pResource, const D3D11_RENDER_TARGET_VIEW_DESC* pDesc,
                                       ID3D11RenderTargetView** ppRTView) {
    const char* call = "CreateRenderTargetView";
    if (auto* l = dynamic_cast<LineTexture*>(pResource); l && &l->device() == this) return lineRenderTargetView(this, l, pDesc, ppRTView);
    HRESULT hr;
    Texture* t = textureOf(this, pResource, call, hr);
    if (!t) return hr;
    if (!(t->desc.BindFlags & D3D11_BIND_RENDER_TARGET))
        return fail(E_INVALIDARG, std::string(call) + ": the texture's BindFlags = " + std::to_string(t->desc.BindFlags) +
                                      " lack D3D11_BIND_RENDER_TARGET");
    if (t->slices() > 1) return arrayRenderTargetView(this, t, pDesc, ppRTView);
    D3D11_RENDER_TARGET_VIEW_DESC d;
    d.Format = t->desc.Format;
    const bool multisampled = t->desc.SampleDesc.Count > 1;
    d.ViewDimension = multisampled ? D3D11_RTV_DIMENSION_TEXTURE2DMS : D3D11_RTV_DIMENSION_TEXTURE2D;
    if (pDesc) {
        if (pDesc->ViewDimension != d.ViewDimension)
            return fail(pDesc->ViewDimension == D3D11_RTV_DIMENSION_UNKNOWN || multisampled || pDesc->ViewDimension == D3D11_RTV_DIMENSION_TEXTURE2DMS
                            ? E_INVALIDARG
                            : E_NOTIMPL,
                        std::string(call) + ": D3D11_RENDER_TARGET_VIEW_DESC.ViewDimension = " + std::to_string(pDesc->ViewDimension) +
                            " (fxport views this texture as D3D11_RTV_DIMENSION_" + (multisampled ? "TEXTURE2DMS" : "TEXTURE2D") + ")");
        if (HRESULT f = checkViewFormat(call, "D3D11_RENDER_TARGET_VIEW_DESC", pDesc->Format, *t, false); FAILED(f)) return f;
        if (HRESULT f = checkStoredFormat(call, "D3D11_RENDER_TARGET_VIEW_DESC", pDesc->Format, *t); FAILED(f)) return f;
        if (pDesc->Format != DXGI_FORMAT_UNKNOWN) d.Format = pDesc->Format;
        if (!multisampled && pDesc->Texture2D.MipSlice != 0)
            return fail(E_NOTIMPL, std::string(call) + ": D3D11_RENDER_TARGET_VIEW_DESC.Texture2D.MipSlice = " +
                                       std::to_string(pDesc->Texture2D.MipSlice) + ": fxport renders into level 0");
    }
    if (!ppRTView) return succeed();
    return guarded(call, [&] {
        auto view = std::unique_ptr<RenderTargetView, void (*)(RenderTargetView*)>(new RenderTargetView(this, t, d),
                                                                                   [](RenderTargetView* v) { v->Release(); });
        if (const SurfaceFormat written = viewSurface(d.Format, *t); written != t->format)
            view->slice = std::make_unique<core::TargetView>(*t->colour, written);  // another member of a typeless family
        *ppRTView = view.release();
        return succeed();
    });
}

HRESULT Device::CreateDepthStencilView(ID3D11Resource* pResource, const D3D11_DEPTH_STENCIL_VIEW_DESC* pDesc,
                                       ID3D11DepthStencilView** ppDepthStencilView) {
    const char* call = "CreateDepthStencilView";
    if (auto* l = dynamic_cast<LineTexture*>(pResource); l && &l->device() == this) return lineDepthStencilView(this, l, pDesc, ppDepthStencilView);
    HRESULT hr;
    Texture* t = textureOf(this, pResource, call, hr);
    if (!t) return hr;
    if (t->slices() > 1 && (t->desc.BindFlags & D3D11_BIND_DEPTH_STENCIL)) {
        if (HRESULT f = needsDescription(call, *t, pDesc != nullptr); FAILED(f)) return f;
        return arrayDepthStencilView(this, t, pDesc, ppDepthStencilView);
    }
    if (!t->depth)
        return fail(E_INVALIDARG, std::string(call) + ": the texture's BindFlags = " + std::to_string(t->desc.BindFlags) +
                                      " lack D3D11_BIND_DEPTH_STENCIL");
    if (HRESULT f = needsDescription(call, *t, pDesc != nullptr); FAILED(f)) return f;
    D3D11_DEPTH_STENCIL_VIEW_DESC d;
    d.Format = t->desc.Format;
    const bool multisampled = t->desc.SampleDesc.Count > 1;
    d.ViewDimension = multisampled ? D3D11_DSV_DIMENSION_TEXTURE2DMS : D3D11_DSV_DIMENSION_TEXTURE2D;
    if (pDesc) {
        if (pDesc->ViewDimension != d.ViewDimension)
            return fail(pDesc->ViewDimension == D3D11_DSV_DIMENSION_UNKNOWN ? E_INVALIDARG : E_NOTIMPL,
                        std::string(call) + ": D3D11_DEPTH_STENCIL_VIEW_DESC.ViewDimension = " + std::to_string(pDesc->ViewDimension));
        if (HRESULT f = checkViewFormat(call, "D3D11_DEPTH_STENCIL_VIEW_DESC", pDesc->Format, *t, true); FAILED(f)) return f;
        const DXGI_FORMAT viewed = pDesc->Format != DXGI_FORMAT_UNKNOWN ? pDesc->Format : t->desc.Format;
        if (HRESULT f = checkDepthViewFlags(std::string(call) + ": D3D11_DEPTH_STENCIL_VIEW_DESC.", pDesc->Flags, viewed); FAILED(f)) return f;
        d.Flags = pDesc->Flags;
        if (pDesc->Texture2D.MipSlice != 0)
            return fail(E_INVALIDARG, std::string(call) + ": D3D11_DEPTH_STENCIL_VIEW_DESC.Texture2D.MipSlice = " +
                                          std::to_string(pDesc->Texture2D.MipSlice) + " (the texture has 1 level)");
    }
    if (pDesc && pDesc->Format != DXGI_FORMAT_UNKNOWN) d.Format = pDesc->Format;
    if (!ppDepthStencilView) return succeed();
    *ppDepthStencilView = new DepthStencilView(this, t, d);
    return succeed();
}

HRESULT Device::CreateUnorderedAccessView(ID3D11Resource* pResource, const D3D11_UNORDERED_ACCESS_VIEW_DESC* pDesc,
                                          ID3D11UnorderedAccessView** ppUAView) {
    const char* call = "CreateUnorderedAccessView";
    if (!pResource) return fail(E_INVALIDARG, std::string(call) + ": pResource is null");
    if (auto* l = dynamic_cast<LineTexture*>(pResource); l && &l->device() == this) {
        if (!(l->desc.BindFlags & D3D11_BIND_UNORDERED_ACCESS))
            return fail(E_INVALIDARG, std::string(call) + ": the resource's BindFlags = " + std::to_string(l->desc.BindFlags) + " lack D3D11_BIND_UNORDERED_ACCESS");
        return lineUnorderedAccessView(this, l, pDesc, ppUAView);
    }
    auto* b = dynamic_cast<Buffer*>(pResource);
    auto* t = dynamic_cast<Texture*>(pResource);
    if ((b && &b->device() != this) || (t && &t->device() != this) || (!b && !t))
        return fail(E_INVALIDARG, std::string(call) + ": pResource was not made by this device");
    const UINT bind = b ? b->desc.BindFlags : t->desc.BindFlags;
    if (!(bind & D3D11_BIND_UNORDERED_ACCESS))
        return fail(E_INVALIDARG, std::string(call) + ": the resource's BindFlags = " + std::to_string(bind) + " lack D3D11_BIND_UNORDERED_ACCESS");
    D3D11_UNORDERED_ACCESS_VIEW_DESC d;
    std::optional<SurfaceFormat> typed;
    BufferRange range;
    if (b) {
        const bool structured = (b->desc.MiscFlags & D3D11_RESOURCE_MISC_BUFFER_STRUCTURED) != 0;
        if (!pDesc && !structured)
            return fail(E_INVALIDARG, std::string(call) + ": pDesc is null for a buffer that is not structured (a raw view needs a description)");
        d.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
        d.Buffer.NumElements = structured ? b->desc.ByteWidth / b->desc.StructureByteStride : 0;
        if (pDesc) {
            d = *pDesc;
            if (d.ViewDimension != D3D11_UAV_DIMENSION_BUFFER)
                return fail(E_INVALIDARG, std::string(call) + ": D3D11_UNORDERED_ACCESS_VIEW_DESC.ViewDimension = " + std::to_string(d.ViewDimension) +
                                              " for a buffer (D3D11_UAV_DIMENSION_BUFFER)");
            if (d.Buffer.Flags & (D3D11_BUFFER_UAV_FLAG_APPEND | D3D11_BUFFER_UAV_FLAG_COUNTER))
                return fail(E_NOTIMPL, std::string(call) + ": D3D11_UNORDERED_ACCESS_VIEW_DESC.Buffer.Flags = " + std::to_string(d.Buffer.Flags) +
                                           ": append and counter UAVs are not supported");
            if (HRESULT hr = checkBufferView(call, "D3D11_UNORDERED_ACCESS_VIEW_DESC.Buffer", *b, d.Format, (d.Buffer.Flags & D3D11_BUFFER_UAV_FLAG_RAW) != 0,
                                             d.Buffer.FirstElement, d.Buffer.NumElements, typed, range);
                FAILED(hr))
                return hr;
        }
    } else {
        d.Format = t->desc.Format;
        d.ViewDimension = D3D11_UAV_DIMENSION_TEXTURE2D;
        if (pDesc) {
            if (pDesc->ViewDimension != D3D11_UAV_DIMENSION_TEXTURE2D)
                return fail(pDesc->ViewDimension == D3D11_UAV_DIMENSION_UNKNOWN ? E_INVALIDARG : E_NOTIMPL,
                            std::string(call) + ": D3D11_UNORDERED_ACCESS_VIEW_DESC.ViewDimension = " + std::to_string(pDesc->ViewDimension) +
                                " for a 2D texture (D3D11_UAV_DIMENSION_TEXTURE2D)");
            if (HRESULT f = checkViewFormat(call, "D3D11_UNORDERED_ACCESS_VIEW_DESC", pDesc->Format, *t, false); FAILED(f)) return f;
            if (HRESULT f = checkStoredFormat(call, "D3D11_UNORDERED_ACCESS_VIEW_DESC", pDesc->Format, *t); FAILED(f)) return f;
            if (pDesc->Format != DXGI_FORMAT_UNKNOWN) d.Format = pDesc->Format;
            if (pDesc->Texture2D.MipSlice != 0)
                return fail(E_NOTIMPL, std::string(call) + ": D3D11_UNORDERED_ACCESS_VIEW_DESC.Texture2D.MipSlice = " +
                                           std::to_string(pDesc->Texture2D.MipSlice) + ": fxport writes level 0");
        }
    }
    if (!ppUAView) return succeed();
    return guarded(call, [&] {
        auto view = std::unique_ptr<UnorderedAccessView, void (*)(UnorderedAccessView*)>(new UnorderedAccessView(this, pResource, b, t, d),
                                                                                         [](UnorderedAccessView* v) { v->Release(); });
        view->range = range;
        if (typed) view->typed = std::make_unique<core::TexelBuffer>(core(), *b->gpu, *typed, std::size_t(range.count), std::size_t(range.first));
        if (t && viewSurface(d.Format, *t) != t->format)  // another member of a typeless family: a GL texture view
            view->formatView = std::make_unique<fxport::Texture2D>(*t->colour, viewSurface(d.Format, *t));
        *ppUAView = view.release();
        return succeed();
    });
}

}  // namespace fxport::d3d11
