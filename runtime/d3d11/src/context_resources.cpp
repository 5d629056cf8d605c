// The immediate context's resource calls: Map/Unmap (CPU copies of dynamic and staging
// resources), UpdateSubresource, CopyResource and CopySubresourceRegion (GPU to GPU through the
// device core; staging sides through CPU memory, as D3D's staging resources are), clears, mips.
#include <algorithm>
#include <cmath>
#include <cstring>

#include "context.h"
#include "guarded.h"

namespace fxport::d3d11 {

HRESULT Context::Map(ID3D11Resource* pResource, UINT Subresource, D3D11_MAP MapType, UINT, D3D11_MAPPED_SUBRESOURCE* out) {
    if (!out) return fail(E_INVALIDARG, "Map: pMappedResource is null");
    const bool reads = MapType == D3D11_MAP_READ || MapType == D3D11_MAP_READ_WRITE;
    const bool writes = MapType != D3D11_MAP_READ;
    if (MapType < D3D11_MAP_READ || MapType > D3D11_MAP_WRITE_NO_OVERWRITE)
        return fail(E_INVALIDARG, "Map: MapType = " + std::to_string(MapType) + " is not a D3D11_MAP value (1-5)");
    auto checkAccess = [&](D3D11_USAGE usage, UINT cpu) -> HRESULT {
        if (usage == D3D11_USAGE_DYNAMIC && MapType != D3D11_MAP_WRITE_DISCARD && MapType != D3D11_MAP_WRITE_NO_OVERWRITE)
            return fail(E_INVALIDARG, "Map: MapType = " + std::to_string(MapType) + " on a USAGE_DYNAMIC resource (WRITE_DISCARD or WRITE_NO_OVERWRITE)");
        if (usage != D3D11_USAGE_DYNAMIC && usage != D3D11_USAGE_STAGING)
            return fail(E_INVALIDARG, "Map: the resource's Usage = " + std::to_string(usage) + " (only DYNAMIC and STAGING resources map)");
        if ((reads && !(cpu & D3D11_CPU_ACCESS_READ)) || (writes && !(cpu & D3D11_CPU_ACCESS_WRITE)))
            return fail(E_INVALIDARG, "Map: MapType = " + std::to_string(MapType) + " needs CPU access the resource's CPUAccessFlags = " +
                                          std::to_string(cpu) + " do not give");
        return S_OK;
    };
    if (auto* b = own<Buffer>(pResource, device_)) {
        if (Subresource != 0) return fail(E_INVALIDARG, "Map: Subresource = " + std::to_string(Subresource) + " of a buffer");
        if (b->mapped) return fail(E_INVALIDARG, "Map: the buffer is already mapped");
        if (HRESULT hr = checkAccess(b->desc.Usage, b->desc.CPUAccessFlags); FAILED(hr)) return hr;
        if (b->cpu.empty()) b->cpu.assign(b->desc.ByteWidth, 0);  // a dynamic buffer's CPU copy, kept for NO_OVERWRITE
        b->mapped = true;
        *out = D3D11_MAPPED_SUBRESOURCE{b->cpu.data(), b->desc.ByteWidth, b->desc.ByteWidth};
        return succeed();
    }
    if (auto* l = own<LineTexture>(pResource, device_)) {
        if (HRESULT hr = checkAccess(l->desc.Usage, l->desc.CPUAccessFlags); FAILED(hr)) return hr;
        return mapLine(*l, Subresource, *out);
    }
    if (auto* t = own<Texture>(pResource, device_)) {
        d3d11::Subresource at;  // the parameter `Subresource` hides the type
        if (!splitSubresource(*t, Subresource, at))
            return fail(E_INVALIDARG, "Map: Subresource = " + std::to_string(Subresource) + " of " + std::to_string(t->subresources()));
        if (t->mappedLevel >= 0) return fail(E_INVALIDARG, "Map: the texture is already mapped");
        if (HRESULT hr = checkAccess(t->desc.Usage, t->desc.CPUAccessFlags); FAILED(hr)) return hr;
        if (t->staging.empty())
            for (int level = 0; level < t->levels; ++level) t->staging.emplace_back(t->levelBytes(level), 0);
        t->mappedLevel = int(Subresource);
        const UINT row = UINT(rowBytes(t->format, t->levelWidth(at.level)));  // of 4x4 blocks for BC formats
        *out = D3D11_MAPPED_SUBRESOURCE{t->staging[Subresource].data(), row, UINT(t->levelBytes(at.level))};
        return succeed();
    }
    return fail(E_INVALIDARG, "Map: pResource is not a buffer or texture of this device");
}

void Context::Unmap(ID3D11Resource* pResource, UINT Subresource) {
    guarded("Unmap", [&] {
        if (auto* b = own<Buffer>(pResource, device_)) {
            if (!b->mapped) return fail(E_INVALIDARG, "Unmap: the buffer is not mapped");
            b->mapped = false;
            if (b->gpu) b->gpu->write(0, b->cpu.size(), b->cpu.data());
            return succeed();
        }
        if (auto* l = own<LineTexture>(pResource, device_)) return unmapLine(*l, Subresource);
        if (auto* t = own<Texture>(pResource, device_)) {
            if (t->mappedLevel != int(Subresource)) return fail(E_INVALIDARG, "Unmap: subresource " + std::to_string(Subresource) + " is not mapped");
            t->mappedLevel = -1;
            if (t->colour) t->colour->setData(int(Subresource), nullptr, t->staging[Subresource].data(), t->staging[Subresource].size());
            return succeed();
        }
        return fail(E_INVALIDARG, "Unmap: pResource is not a buffer or texture of this device");
    });
}

void Context::UpdateSubresource(ID3D11Resource* pDst, UINT DstSubresource, const D3D11_BOX* box, const void* pSrcData, UINT SrcRowPitch, UINT) {
    if (predicatedAway()) return;  // SetPredication
    guarded("UpdateSubresource", [&] {
        if (!pSrcData) return fail(E_INVALIDARG, "UpdateSubresource: pSrcData is null");
        if (auto* b = own<Buffer>(pDst, device_)) {
            if (b->desc.Usage != D3D11_USAGE_DEFAULT)
                return fail(E_INVALIDARG, "UpdateSubresource: the buffer's Usage = " + std::to_string(b->desc.Usage) + " (only USAGE_DEFAULT)");
            if (box && (b->desc.BindFlags & D3D11_BIND_CONSTANT_BUFFER))
                return fail(E_INVALIDARG, "UpdateSubresource: a constant buffer is updated whole (pDstBox must be null)");
            const UINT left = box ? box->left : 0, right = box ? box->right : b->desc.ByteWidth;
            if (right <= left || right > b->desc.ByteWidth)
                return fail(E_INVALIDARG, "UpdateSubresource: box [" + std::to_string(left) + ", " + std::to_string(right) + ") of a " +
                                              std::to_string(b->desc.ByteWidth) + "-byte buffer");
            b->gpu->write(left, right - left, pSrcData);
            return succeed();
        }
        if (auto* l = own<LineTexture>(pDst, device_)) return updateLine(*l, DstSubresource, box, pSrcData);
        auto* t = own<Texture>(pDst, device_);
        if (!t) return fail(E_INVALIDARG, "UpdateSubresource: pDstResource is not a buffer or texture of this device");
        if (t->desc.Usage != D3D11_USAGE_DEFAULT || !(t->colour || t->array))
            return fail(E_INVALIDARG, "UpdateSubresource: the texture is not a USAGE_DEFAULT colour texture");
        Subresource at;
        if (!splitSubresource(*t, DstSubresource, at))
            return fail(E_INVALIDARG, "UpdateSubresource: DstSubresource = " + std::to_string(DstSubresource) + " of " + std::to_string(t->subresources()));
        const int level = at.level;
        Rectangle r(0, 0, t->levelWidth(level), t->levelHeight(level));
        if (box) r = Rectangle(int(box->left), int(box->top), int(box->right) - int(box->left), int(box->bottom) - int(box->top));
        const std::size_t row = rowBytes(t->format, r.Width);  // of 4x4 blocks for BC formats
        if (SrcRowPitch < row) return fail(E_INVALIDARG, "UpdateSubresource: SrcRowPitch = " + std::to_string(SrcRowPitch) + " < " + std::to_string(row));
        const int rows = rowCount(t->format, r.Height);
        std::vector<std::uint8_t> packed(row * std::size_t(rows));
        for (int y = 0; y < rows; ++y)
            std::memcpy(&packed[std::size_t(y) * row], static_cast<const std::uint8_t*>(pSrcData) + std::size_t(y) * SrcRowPitch, row);
        writeSubresource(*t, at, &r, packed);
        return succeed();
    });
}

void Context::CopyResource(ID3D11Resource* pDst, ID3D11Resource* pSrc) {
    if (predicatedAway()) return;  // SetPredication
    guarded("CopyResource", [&] {
        auto *bd = own<Buffer>(pDst, device_), *bs = own<Buffer>(pSrc, device_);
        if (bd && bs) {
            if (bd->desc.ByteWidth != bs->desc.ByteWidth) return fail(E_INVALIDARG, "CopyResource: the buffers differ in ByteWidth");
            if (bd->gpu && bs->gpu) bd->gpu->copyFrom(*bs->gpu);
            else if (bd->gpu) bd->gpu->write(0, bs->cpu.size(), bs->cpu.data());
            else if (bs->gpu) bs->gpu->read(0, bd->cpu.size(), bd->cpu.data());
            else bd->cpu = bs->cpu;
            return succeed();
        }
        auto *ld = own<LineTexture>(pDst, device_), *ls = own<LineTexture>(pSrc, device_);
        if (ld && ls) return copyLines(*ld, *ls);
        auto *td = own<Texture>(pDst, device_), *ts = own<Texture>(pSrc, device_);
        if (!td || !ts) return fail(E_INVALIDARG, "CopyResource: the resources are not two buffers or two textures (of one dimension) of this device");
        if (td->desc.Width != ts->desc.Width || td->desc.Height != ts->desc.Height || td->desc.Format != ts->desc.Format ||
            td->levels != ts->levels)
            return fail(E_INVALIDARG, "CopyResource: the textures differ in size, format or mip levels");
        if (td->desc.SampleDesc.Count != ts->desc.SampleDesc.Count)
            return fail(E_INVALIDARG, "CopyResource: the textures differ in SampleDesc.Count (a multisampled texture is read through ResolveSubresource)");
        // A typeless depth texture (R32/R24G8/R16_TYPELESS with SHADER_RESOURCE) is a texture under its
        // depth buffer: copied as one. A depth buffer alone (no SRV) has no texels fxport can copy yet.
        if ((td->depth && !td->colour) || (ts->depth && !ts->colour))
            return fail(E_NOTIMPL, "CopyResource: a depth-stencil texture without BIND_SHADER_RESOURCE (a typeless one with it copies)");
        if (td->slices() != ts->slices()) return fail(E_INVALIDARG, "CopyResource: the textures differ in ArraySize");
        if (td->slices() > 1 && td->desc.SampleDesc.Count > 1)
            return fail(E_NOTIMPL, "CopyResource: multisampled arrays (SampleDesc.Count = " + std::to_string(td->desc.SampleDesc.Count) +
                                       ") are not copied yet: resolve their slices (ResolveSubresource)");
        if (td->slices() > 1) {  // arrays: subresource by subresource (through the CPU when one side is staging)
            Subresource at;
            for (UINT sub = 0; splitSubresource(*ts, sub, at); ++sub) writeSubresource(*td, at, nullptr, readSubresource(*ts, at));
            return succeed();
        }
        if (td->cube && ts->cube) {
            core::copyTexture(*td->cube, *ts->cube);  // every face and level
            return succeed();
        }
        if (td->cube || ts->cube) return fail(E_INVALIDARG, "CopyResource: a cube texture copies to a cube texture only");
        for (int level = 0; level < ts->levels; ++level) {
            if (td->colour && ts->colour) {
                core::copyTexture(*td->colour, *ts->colour);
                break;
            }
            auto& cpu = td->colour ? ts->staging[std::size_t(level)] : td->staging[std::size_t(level)];
            if (td->colour) td->colour->setData(level, nullptr, cpu.data(), cpu.size());
            else if (ts->colour) ts->colour->getData(level, cpu.data(), cpu.size());
            else td->staging = ts->staging;
        }
        return succeed();
    });
}

namespace {

// Rows of `width` texels between two tightly packed levels (staging textures' memory).
void copyRows(const std::vector<std::uint8_t>& from, int fromWidth, int fx, int fy, std::vector<std::uint8_t>& to, int toWidth, int tx, int ty,
              int width, int height, int texel) {
    for (int row = 0; row < height; ++row)
        std::memcpy(&to[(std::size_t(ty + row) * std::size_t(toWidth) + std::size_t(tx)) * std::size_t(texel)],
                    &from[(std::size_t(fy + row) * std::size_t(fromWidth) + std::size_t(fx)) * std::size_t(texel)],
                    std::size_t(width) * std::size_t(texel));
}

}  // namespace

void Context::CopySubresourceRegion(ID3D11Resource* pDst, UINT DstSubresource, UINT DstX, UINT DstY, UINT DstZ, ID3D11Resource* pSrc,
                                    UINT SrcSubresource, const D3D11_BOX* box) {
    if (predicatedAway()) return;  // SetPredication
    const char* call = "CopySubresourceRegion";
    guarded(call, [&] {
        const std::string at = std::string(call) + ": ";
        if (box && (box->front != 0 || box->back != 1))
            return fail(E_INVALIDARG, at + "pSrcBox front/back = " + std::to_string(box->front) + "/" + std::to_string(box->back) + " (2D: 0/1)");
        if (DstZ != 0) return fail(E_INVALIDARG, at + "DstZ = " + std::to_string(DstZ) + " (2D resources: 0)");
        auto *bd = own<Buffer>(pDst, device_), *bs = own<Buffer>(pSrc, device_);
        if (bd && bs) {
            if (DstSubresource != 0 || SrcSubresource != 0) return fail(E_INVALIDARG, at + "a buffer has one subresource (0)");
            const UINT left = box ? box->left : 0, right = box ? box->right : bs->desc.ByteWidth;
            if (right <= left || right > bs->desc.ByteWidth || DstX > bd->desc.ByteWidth || right - left > bd->desc.ByteWidth - DstX)
                return fail(E_INVALIDARG, at + "bytes [" + std::to_string(left) + ", " + std::to_string(right) + ") of a " + std::to_string(bs->desc.ByteWidth) +
                                              "-byte buffer to byte " + std::to_string(DstX) + " of a " + std::to_string(bd->desc.ByteWidth) + "-byte one");
            const UINT bytes = right - left;
            if (bd->gpu && bs->gpu) bd->gpu->copyFrom(*bs->gpu, left, DstX, bytes);
            else if (bd->gpu) bd->gpu->write(DstX, bytes, bs->cpu.data() + left);
            else if (bs->gpu) bs->gpu->read(left, bytes, bd->cpu.data() + DstX);
            else std::memmove(bd->cpu.data() + DstX, bs->cpu.data() + left, bytes);
            return succeed();
        }
        auto *ld = own<LineTexture>(pDst, device_), *ls = own<LineTexture>(pSrc, device_);
        if (ld && ls) {
            if (DstY != 0) return fail(E_INVALIDARG, at + "DstY = " + std::to_string(DstY) + " (1D textures: 0)");
            return copyLineRegion(*ld, DstSubresource, DstX, *ls, SrcSubresource, box);
        }
        auto *td = own<Texture>(pDst, device_), *ts = own<Texture>(pSrc, device_);
        if (!td || !ts) return fail(E_INVALIDARG, at + "the resources are not two buffers or two textures (of one dimension) of this device");
        if (td->desc.Format != ts->desc.Format)
            return fail(E_INVALIDARG, at + "the textures' formats differ (" + std::string(formatName(td->desc.Format)) + ", " + formatName(ts->desc.Format) + ")");
        if (td->depth || ts->depth) return fail(E_NOTIMPL, at + "depth-stencil textures cannot be copied in fxport yet");
        if (td->cube || ts->cube) return fail(E_NOTIMPL, at + "cube textures cannot be copied in fxport yet");
        Subresource from, to;
        if (!splitSubresource(*td, DstSubresource, to) || !splitSubresource(*ts, SrcSubresource, from))
            return fail(E_INVALIDARG, at + "DstSubresource = " + std::to_string(DstSubresource) + ", SrcSubresource = " + std::to_string(SrcSubresource) +
                                          " (the textures have " + std::to_string(td->subresources()) + " and " + std::to_string(ts->subresources()) +
                                          " subresources)");
        const int sl = from.level, dl = to.level;
        Rectangle area(0, 0, ts->levelWidth(sl), ts->levelHeight(sl));
        if (box) area = Rectangle(int(box->left), int(box->top), int(box->right) - int(box->left), int(box->bottom) - int(box->top));
        if (area.Width <= 0 || area.Height <= 0 || (box && (box->right > UINT(ts->levelWidth(sl)) || box->bottom > UINT(ts->levelHeight(sl)))))
            return fail(E_INVALIDARG, at + "pSrcBox {" + std::to_string(area.X) + ", " + std::to_string(area.Y) + ", " + std::to_string(area.X + area.Width) +
                                          ", " + std::to_string(area.Y + area.Height) + "} is empty or outside source level " + std::to_string(sl));
        if (DstX + UINT(area.Width) > UINT(td->levelWidth(dl)) || DstY + UINT(area.Height) > UINT(td->levelHeight(dl)))
            return fail(E_INVALIDARG, at + "the region at (" + std::to_string(DstX) + ", " + std::to_string(DstY) + ") overruns destination level " +
                                          std::to_string(dl));
        const int x = int(DstX), y = int(DstY);
        if (td->colour && ts->colour) {
            core::copyTextureRegion(*td->colour, dl, x, y, *ts->colour, sl, area);
            return succeed();
        }
        // A whole level read back into a staging level of the same size (screenshots, probes, every
        // frame in some programs): straight into the staging memory, not through two copies.
        if (!td->staging.empty() && ts->staging.empty() && !box && x == 0 && y == 0 &&
            ts->levelWidth(sl) == td->levelWidth(dl) && ts->levelHeight(sl) == td->levelHeight(dl)) {
            readSubresourceInto(*ts, from, td->staging[std::size_t(to.slice * td->levels + to.level)]);
            return succeed();
        }
        // Staging or an array on one side or both: through the CPU (a GPU texture's whole subresource is read),
        // in units of 4x4 blocks for BC formats (whose boxes D3D puts on the block grid).
        const int texel = bytesPerPixel(ts->format), block = isCompressedFormat(ts->format) ? 4 : 1;
        const std::vector<std::uint8_t> source = readSubresource(*ts, from);
        const int across = int(rowBytes(ts->format, area.Width)) / texel, down = rowCount(ts->format, area.Height);
        std::vector<std::uint8_t> packed(std::size_t(across) * std::size_t(down) * std::size_t(texel));
        copyRows(source, int(rowBytes(ts->format, ts->levelWidth(sl))) / texel, area.X / block, area.Y / block, packed, across, 0, 0, across, down, texel);
        const Rectangle target(x, y, area.Width, area.Height);
        writeSubresource(*td, to, &target, packed);
        return succeed();
    });
}

void Context::ClearRenderTargetView(ID3D11RenderTargetView* p, const FLOAT c[4]) {
    if (predicatedAway()) return;  // SetPredication
    guarded("ClearRenderTargetView", [&] {
        auto* v = own<RenderTargetView>(p, device_);
        if (!v || !c) return fail(E_INVALIDARG, "ClearRenderTargetView: no view of this device, or no colour");
        // D3D converts the colour to the view's format: an _SRGB view stores it sRGB-encoded.
        const SurfaceFormat f = v->target().Format();
        const bool srgb = f == SurfaceFormat::ColorSRgb || f == SurfaceFormat::Bgra32SRgb || f == SurfaceFormat::Bgrx32SRgb;
        auto encoded = [srgb](FLOAT linear) {
            if (!srgb) return linear;
            const float x = std::clamp(linear, 0.0f, 1.0f);
            return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
        };
        core::clearTexture(v->target(), Vector4(encoded(c[0]), encoded(c[1]), encoded(c[2]), c[3]));
        return succeed();
    });
}

void Context::ClearDepthStencilView(ID3D11DepthStencilView* p, UINT flags, FLOAT depth, UINT8 stencil) {
    if (predicatedAway()) return;  // SetPredication
    guarded("ClearDepthStencilView", [&] {
        auto* v = own<DepthStencilView>(p, device_);
        if (!v) return fail(E_INVALIDARG, "ClearDepthStencilView: no view of this device");
        core::clearDepthBuffer(device_->core(), v->buffer(), (flags & D3D11_CLEAR_DEPTH) != 0, (flags & D3D11_CLEAR_STENCIL) != 0,
                               depth, int(stencil));
        return succeed();
    });
}

void Context::GenerateMips(ID3D11ShaderResourceView* p) {
    if (predicatedAway()) return;  // SetPredication
    auto* v = own<ShaderResourceView>(p, device_);
    if (v && v->line) {
        if (!(v->line->desc.MiscFlags & D3D11_RESOURCE_MISC_GENERATE_MIPS))
            return note("GenerateMips: the view's 1D texture was not made with D3D11_RESOURCE_MISC_GENERATE_MIPS");
        guarded("GenerateMips", [&] {
            core::generateMips(*v->line->texels);  // every slice of an array
            return succeed();
        });
        return;
    }
    if (!v || !v->texture || !(v->texture->desc.MiscFlags & D3D11_RESOURCE_MISC_GENERATE_MIPS))
        return note("GenerateMips: the view's texture was not made with D3D11_RESOURCE_MISC_GENERATE_MIPS");
    guarded("GenerateMips", [&] {
        core::generateMips(*v->texture->sampled());  // every slice of an array
        return succeed();
    });
}

void Context::Flush() { device_->core().finish(); }

}  // namespace fxport::d3d11
