// The D3D11 session's resources (see d3d11_session.h): render targets, textures, buffers and their
// views from the resource blocks, and their read-back through staging copies and Map.
#include <algorithm>
#include <cstring>

#include "d3d11_session.h"

namespace conformance {

using namespace fxport::d3d11;

namespace {

constexpr int kDefaultWidth = 640;   // vkd3d's RENDER_TARGET_WIDTH
constexpr int kDefaultHeight = 480;  // RENDER_TARGET_HEIGHT
constexpr int kDepthSlot = -1;       // the [dsv] in the map of targets not made

// A failed Create* call: the front end's sentence, as a skip of what needs the object.
void check(HRESULT hr, const std::string& what) {
    if (FAILED(hr)) throw Unsupported(what + ": " + GetLastErrorMessage());
}

// The data words of `r`, `count` of them (0 past the data given).
std::vector<std::uint32_t> wordsOf(const ResourceDesc& r, std::size_t first, std::size_t count) {
    std::vector<std::uint32_t> words(count, 0);
    for (std::size_t k = 0; k < count && first + k < r.data.size(); ++k) words[k] = r.data[first + k];
    return words;
}

bool isBuffer(const ResourceDesc& r) { return r.dimension == "buffer" || r.dimension == "raw_buffer"; }
// Bytes of one element of a buffer: the structure, a raw word, or one typed texel.
UINT elementBytes(const ResourceDesc& r) {
    if (r.dimension == "raw_buffer") return 4;
    return r.stride > 0 ? UINT(r.stride) : UINT(texelBytes(r.format));
}

// A [srv N] of dimension 2dms: a multisampled render target a shader reads through a TEXTURE2DMS
// view; D3D gives a multisampled texture no initial data, so one with data is skipped.
void makeMultisampleView(ID3D11Device& device, const ResourceDesc& r, ComPtr<ID3D11ShaderResourceView>& view) {
    if (!r.data.empty()) throw Unsupported("a multisampled [srv N] with data (D3D makes multisampled textures without initial data)");
    D3D11_TEXTURE2D_DESC d;
    d.Width = UINT(r.width);
    d.Height = UINT(r.height);
    d.MipLevels = d.ArraySize = 1;
    d.Format = dxgiFormat(r.format);
    d.SampleDesc.Count = UINT(r.samples);
    d.BindFlags = D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_RENDER_TARGET;
    ComPtr<ID3D11Texture2D> texture;
    const std::string what = "multisampled texture [srv " + std::to_string(r.slot) + "] " + r.format.name;
    check(device.CreateTexture2D(&d, nullptr, texture.GetAddressOf()), what);
    check(device.CreateShaderResourceView(texture.Get(), nullptr, view.GetAddressOf()), what);
}

// A [srv N] of dimension 3d: one subresource per level, vkd3d's data slice by slice.
void makeVolumeView(ID3D11Device& device, const ResourceDesc& r, ComPtr<ID3D11ShaderResourceView>& view) {
    D3D11_TEXTURE3D_DESC d;
    d.Width = UINT(r.width);
    d.Height = UINT(r.height);
    d.Depth = UINT(r.depth);
    d.MipLevels = UINT(r.levels);
    d.Format = dxgiFormat(r.format);
    d.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    std::vector<std::vector<std::uint32_t>> levels(std::size_t(r.levels));
    std::vector<D3D11_SUBRESOURCE_DATA> data;
    std::size_t at = 0;
    for (int level = 0; level < r.levels; ++level) {
        const int w = std::max(1, r.width >> level), h = std::max(1, r.height >> level), z = std::max(1, r.depth >> level);
        levels[std::size_t(level)] = wordsOf(r, at, std::size_t(w * h * z * r.format.components));
        at += levels[std::size_t(level)].size();
        const UINT row = UINT(w * texelBytes(r.format));
        data.push_back({levels[std::size_t(level)].data(), row, row * UINT(h)});
    }
    ComPtr<ID3D11Texture3D> texture;
    const std::string what = "3D texture [srv " + std::to_string(r.slot) + "] " + r.format.name;
    check(device.CreateTexture3D(&d, data.data(), texture.GetAddressOf()), what);
    check(device.CreateShaderResourceView(texture.Get(), nullptr, view.GetAddressOf()), what);
}

}  // namespace

void D3d11Session::forgetReadbacks() {
    for (auto& [slot, t] : targets_) t.readback.clear();
    for (auto& [slot, u] : uavs_) u.readback.clear();
}

void D3d11Session::setResource(const ResourceDesc& r) {
    switch (r.kind) {
    case BlockKind::Rtv: makeTarget(r); break;
    case BlockKind::Dsv: unmadeTargets_[kDepthSlot] = "depth-stencil view [dsv] (the D3D11 session makes no depth buffer: no depth readback)"; break;
    case BlockKind::Srv: isBuffer(r) ? makeBufferSrv(r) : makeTexture(r); break;
    case BlockKind::VertexBuffer: vertexBuffers_[r.slot] = r; break;
    case BlockKind::Uav: makeUav(r); break;
    default: throw Unsupported("resource kind of this block");
    }
}

void D3d11Session::setSampler(const SamplerDesc& s) {
    samplers_.erase(s.slot);
    unmadeSamplers_.erase(s.slot);
    try {
        D3D11_SAMPLER_DESC d = samplerDescOf(s);
        check(device_->CreateSamplerState(&d, samplers_[s.slot].GetAddressOf()), "[sampler " + std::to_string(s.slot) + "]");
    } catch (const Unsupported& e) {
        samplers_.erase(s.slot);
        unmadeSamplers_[s.slot] = e.what();
    }
}

void D3d11Session::makeTarget(const ResourceDesc& r) {
    targets_.erase(r.slot);
    unmadeTargets_.erase(r.slot);
    try {
        if (r.dimension != "2d" && r.dimension != "2dms") throw Unsupported("render target dimension " + r.dimension);
        D3D11_TEXTURE2D_DESC d;
        d.Width = UINT(r.width);
        d.Height = UINT(r.height);
        d.MipLevels = d.ArraySize = 1;
        if (r.dimension == "2dms") d.SampleDesc.Count = UINT(r.samples);
        d.Format = dxgiFormat(r.format);
        d.BindFlags = D3D11_BIND_RENDER_TARGET;
        Texture t;
        t.desc = r;
        const std::string what = "render target " + r.format.name;
        check(device_->CreateTexture2D(&d, nullptr, t.texture.GetAddressOf()), what);
        check(device_->CreateRenderTargetView(t.texture.Get(), nullptr, t.rtv.GetAddressOf()), what);
        const float zero[4] = {0, 0, 0, 0};
        context_->ClearRenderTargetView(t.rtv.Get(), zero);
        targets_[r.slot] = std::move(t);
    } catch (const Unsupported& e) {
        unmadeTargets_[r.slot] = e.what();
    }
}

void D3d11Session::ensureDefaultTarget() {
    if (targets_.count(0) || unmadeTargets_.count(0) || unmadeTargets_.count(kDepthSlot)) return;
    ResourceDesc r;
    r.kind = BlockKind::Rtv;
    r.width = kDefaultWidth;
    r.height = kDefaultHeight;
    makeTarget(r);
}

void D3d11Session::makeTexture(const ResourceDesc& r) {
    srvs_.erase(r.slot);
    unmadeSrvs_.erase(r.slot);
    try {
        if (r.dimension == "3d") return makeVolumeView(*device_.Get(), r, srvs_[r.slot]);
        if (r.dimension == "2dms") return makeMultisampleView(*device_.Get(), r, srvs_[r.slot]);
        const bool cube = r.dimension == "cube";
        if (r.dimension != "2d" && !cube) throw Unsupported("texture dimension " + r.dimension + " from [srv N]");
        D3D11_TEXTURE2D_DESC d;
        d.Width = UINT(r.width);
        d.Height = UINT(r.height);
        d.MipLevels = UINT(r.levels);
        d.ArraySize = cube ? 6 : 1;
        d.Format = dxgiFormat(r.format);
        d.BindFlags = D3D11_BIND_SHADER_RESOURCE;
        if (cube) d.MiscFlags = D3D11_RESOURCE_MISC_TEXTURECUBE;
        // Subresources face by face (D3D's order, as vkd3d lists the data), each face's levels in turn.
        std::vector<std::vector<std::uint32_t>> levels(std::size_t(r.levels) * d.ArraySize);
        std::vector<D3D11_SUBRESOURCE_DATA> data;
        std::size_t at = 0;
        for (std::size_t sub = 0; sub < levels.size(); ++sub) {
            const int level = int(sub % std::size_t(r.levels));
            const int w = std::max(1, r.width >> level), h = std::max(1, r.height >> level);
            levels[sub] = wordsOf(r, at, std::size_t(w * h * r.format.components));
            at += levels[sub].size();
            data.push_back({levels[sub].data(), UINT(w * texelBytes(r.format)), 0});
        }
        ComPtr<ID3D11Texture2D> texture;
        const std::string what = "texture [srv " + std::to_string(r.slot) + "] " + r.format.name;
        check(device_->CreateTexture2D(&d, data.data(), texture.GetAddressOf()), what);
        D3D11_SHADER_RESOURCE_VIEW_DESC view;
        view.Format = r.format.shadow ? DXGI_FORMAT_R32_FLOAT : d.Format;
        view.ViewDimension = cube ? D3D11_SRV_DIMENSION_TEXTURECUBE : D3D11_SRV_DIMENSION_TEXTURE2D;
        view.Texture2D.MipLevels = view.TextureCube.MipLevels = UINT(-1);
        check(device_->CreateShaderResourceView(texture.Get(), &view, srvs_[r.slot].GetAddressOf()), what);
    } catch (const Unsupported& e) {
        srvs_.erase(r.slot);
        unmadeSrvs_[r.slot] = e.what();
    }
}

// A buffer of `r`'s elements and data: structured (stride N), raw (32-bit words) or typed (format).
D3d11Session::ComPtr<ID3D11Buffer> D3d11Session::makeBuffer(const ResourceDesc& r, UINT bind) {
    if (r.width <= 0) throw Unsupported("buffer of no elements");
    D3D11_BUFFER_DESC d;
    d.ByteWidth = UINT(r.width) * elementBytes(r);
    d.BindFlags = bind;
    if (r.dimension == "raw_buffer") d.MiscFlags = D3D11_RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS;
    else if (r.stride > 0) d.MiscFlags = D3D11_RESOURCE_MISC_BUFFER_STRUCTURED;
    d.StructureByteStride = r.stride > 0 ? UINT(r.stride) : 0;
    std::vector<std::uint32_t> words = wordsOf(r, 0, d.ByteWidth / 4);
    D3D11_SUBRESOURCE_DATA data{words.data(), 0, 0};
    ComPtr<ID3D11Buffer> buffer;
    check(device_->CreateBuffer(&d, &data, buffer.GetAddressOf()), "buffer of " + std::to_string(r.width) + " elements");
    return buffer;
}

void D3d11Session::makeBufferSrv(const ResourceDesc& r) {
    srvs_.erase(r.slot);
    unmadeSrvs_.erase(r.slot);
    try {
        ComPtr<ID3D11Buffer> buffer = makeBuffer(r, D3D11_BIND_SHADER_RESOURCE);
        D3D11_SHADER_RESOURCE_VIEW_DESC d;
        d.ViewDimension = r.dimension == "raw_buffer" ? D3D11_SRV_DIMENSION_BUFFEREX : D3D11_SRV_DIMENSION_BUFFER;
        d.Format = r.dimension == "raw_buffer" ? DXGI_FORMAT_R32_TYPELESS : r.stride > 0 ? DXGI_FORMAT_UNKNOWN : dxgiFormat(r.format);
        d.Buffer.NumElements = UINT(r.width);
        d.BufferEx.NumElements = UINT(r.width);
        d.BufferEx.Flags = r.dimension == "raw_buffer" ? UINT(D3D11_BUFFEREX_SRV_FLAG_RAW) : 0u;
        check(device_->CreateShaderResourceView(buffer.Get(), &d, srvs_[r.slot].GetAddressOf()), "buffer [srv " + std::to_string(r.slot) + "]");
    } catch (const Unsupported& e) {
        srvs_.erase(r.slot);
        unmadeSrvs_[r.slot] = e.what();
    }
}

void D3d11Session::makeUav(const ResourceDesc& r) {
    uavs_.erase(r.slot);
    unmadeUavs_.erase(r.slot);
    try {
        Uav uav;
        uav.desc = r;
        D3D11_UNORDERED_ACCESS_VIEW_DESC d;
        if (isBuffer(r)) {
            ComPtr<ID3D11Buffer> buffer = makeBuffer(r, D3D11_BIND_UNORDERED_ACCESS);
            uav.resource = ComPtr<ID3D11Resource>(buffer.Get());
            d.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
            d.Format = r.dimension == "raw_buffer" ? DXGI_FORMAT_R32_TYPELESS : r.stride > 0 ? DXGI_FORMAT_UNKNOWN : dxgiFormat(r.format);
            d.Buffer.NumElements = UINT(r.width);
            d.Buffer.Flags = r.dimension == "raw_buffer" ? UINT(D3D11_BUFFER_UAV_FLAG_RAW) : 0u;
        } else if (r.dimension == "2d") {
            D3D11_TEXTURE2D_DESC t;
            t.Width = UINT(r.width);
            t.Height = UINT(r.height);
            t.MipLevels = t.ArraySize = 1;
            t.Format = dxgiFormat(r.format);
            t.BindFlags = D3D11_BIND_UNORDERED_ACCESS;
            std::vector<std::uint32_t> words = wordsOf(r, 0, std::size_t(r.width * r.height * r.format.components));
            D3D11_SUBRESOURCE_DATA data{words.data(), UINT(r.width * texelBytes(r.format)), 0};
            ComPtr<ID3D11Texture2D> texture;
            check(device_->CreateTexture2D(&t, &data, texture.GetAddressOf()), "UAV texture " + r.format.name);
            uav.resource = ComPtr<ID3D11Resource>(texture.Get());
            d.ViewDimension = D3D11_UAV_DIMENSION_TEXTURE2D;
            d.Format = t.Format;
        } else {
            throw Unsupported("UAV dimension " + r.dimension);
        }
        check(device_->CreateUnorderedAccessView(uav.resource.Get(), &d, uav.view.GetAddressOf()), "[uav " + std::to_string(r.slot) + "]");
        uavs_[r.slot] = std::move(uav);
    } catch (const Unsupported& e) {
        unmadeUavs_[r.slot] = e.what();
    }
}

// A CPU-readable (USAGE_STAGING) resource like `resource` (level 0 of a texture): its row bytes and rows.
D3d11Session::ComPtr<ID3D11Resource> D3d11Session::stagingFor(ID3D11Resource* resource, const ResourceDesc& r, std::size_t& rowBytes,
                                                              std::size_t& rows) {
    HRESULT hr = S_OK;
    ComPtr<ID3D11Resource> staging;
    if (isBuffer(r)) {
        D3D11_BUFFER_DESC d;
        static_cast<ID3D11Buffer*>(resource)->GetDesc(&d);
        rowBytes = d.ByteWidth;
        rows = 1;
        D3D11_BUFFER_DESC s;
        s.ByteWidth = d.ByteWidth;
        s.Usage = D3D11_USAGE_STAGING;
        s.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
        ComPtr<ID3D11Buffer> b;
        hr = device_->CreateBuffer(&s, nullptr, b.GetAddressOf());
        staging = ComPtr<ID3D11Resource>(b.Get());
    } else {
        D3D11_TEXTURE2D_DESC d;
        static_cast<ID3D11Texture2D*>(resource)->GetDesc(&d);
        rowBytes = std::size_t(d.Width) * std::size_t(texelBytes(r.format));
        rows = d.Height;
        d.MipLevels = 1;
        d.Usage = D3D11_USAGE_STAGING;
        d.BindFlags = 0;
        d.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
        ComPtr<ID3D11Texture2D> t;
        hr = device_->CreateTexture2D(&d, nullptr, t.GetAddressOf());
        staging = ComPtr<ID3D11Resource>(t.Get());
    }
    if (FAILED(hr)) throw std::runtime_error(std::string("staging copy for a probe: ") + GetLastErrorMessage());
    return staging;
}

// The texture behind render target or shader-resource view `slot`.
D3d11Session::ComPtr<ID3D11Resource> D3d11Session::resourceOf(const std::string& kind, int slot) {
    if (kind == "rtv" && targets_.count(slot)) return ComPtr<ID3D11Resource>(targets_[slot].texture.Get());
    if (kind == "srv" && srvs_.count(slot)) {
        ComPtr<ID3D11Resource> resource;
        srvs_[slot]->GetResource(resource.GetAddressOf());
        return resource;
    }
    throw Unsupported("copy of " + kind + " " + std::to_string(slot) + ", which the session has not made");
}

void D3d11Session::copyResource(const std::string& fromKind, int fromSlot, const std::string& toKind, int toSlot) {
    ComPtr<ID3D11Resource> from = resourceOf(fromKind, fromSlot), to = resourceOf(toKind, toSlot);
    context_->CopyResource(to.Get(), from.Get());
    if (*GetLastErrorMessage()) throw std::runtime_error(std::string("CopyResource: ") + GetLastErrorMessage());
}

// A single-sample copy of multisampled `texture`, each pixel its samples' average: what vkd3d's d3d11
// runner probes (ResolveSubresource into a USAGE_DEFAULT texture).
D3d11Session::ComPtr<ID3D11Resource> D3d11Session::resolved(ID3D11Texture2D* texture) {
    D3D11_TEXTURE2D_DESC d;
    texture->GetDesc(&d);
    d.SampleDesc.Count = 1;
    d.SampleDesc.Quality = 0;
    d.BindFlags = 0;
    ComPtr<ID3D11Texture2D> single;
    if (FAILED(device_->CreateTexture2D(&d, nullptr, single.GetAddressOf())))
        throw std::runtime_error(std::string("resolved copy for a probe: ") + GetLastErrorMessage());
    context_->ResolveSubresource(single.Get(), 0, texture, 0, d.Format);
    if (*GetLastErrorMessage()) throw std::runtime_error(std::string("resolve for a probe: ") + GetLastErrorMessage());
    return ComPtr<ID3D11Resource>(single.Get());
}

// Level 0 of a texture or the whole of a buffer as 32-bit words, rows packed (a staging copy, Map;
// a multisampled texture resolved first). A target is read after every draw: its staging copy is
// kept (one per resource; the session holds the resource, so its address is not reused) and
// `words` keeps its memory, so that no read-back allocates and zero-fills megabytes again.
void D3d11Session::readBack(ID3D11Resource* resource, const ResourceDesc& r, std::vector<std::uint32_t>& words) {
    ComPtr<ID3D11Resource> single;
    if (r.dimension == "2dms") {
        single = resolved(static_cast<ID3D11Texture2D*>(resource));
        resource = single.Get();
    }
    std::size_t rowBytes = 0, rows = 0;
    ComPtr<ID3D11Resource> staging;
    auto kept = stagingCopies_.find(resource);
    if (kept != stagingCopies_.end()) staging = kept->second.staging, rowBytes = kept->second.rowBytes, rows = kept->second.rows;
    else {
        staging = stagingFor(resource, r, rowBytes, rows);
        if (!single) stagingCopies_[resource] = StagingCopy{ComPtr<ID3D11Resource>(resource), staging, rowBytes, rows};
    }
    context_->CopySubresourceRegion(staging.Get(), 0, 0, 0, 0, resource, 0, nullptr);
    D3D11_MAPPED_SUBRESOURCE m;
    if (FAILED(context_->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &m))) throw std::runtime_error(GetLastErrorMessage());
    words.resize(rowBytes / 4 * rows);
    for (std::size_t y = 0; y < rows; ++y)
        std::memcpy(words.data() + y * rowBytes / 4, static_cast<const char*>(m.pData) + y * m.RowPitch, rowBytes);
    context_->Unmap(staging.Get(), 0);
}

namespace {

// A texel of `words` (rows of `width` texels of `components` words), widened as the XNA session's
// Vector4 read-back is: missing float components 0, alpha 1.
Texel texelAt(const std::vector<std::uint32_t>& words, const ResourceDesc& r, int width, int x, int y) {
    Texel t;
    const std::size_t at = (std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(r.format.components);
    if (r.format.type == 'f' && r.format.components < 4) {
        const float one = 1.0f;
        std::memcpy(&t.bits[3], &one, 4);
    }
    for (int k = 0; k < r.format.components && at + std::size_t(k) < words.size(); ++k) t.bits[std::size_t(k)] = words[at + std::size_t(k)];
    return t;
}

}  // namespace

Texel D3d11Session::readTexel(int slot, int x, int y) {
    auto it = targets_.find(slot);
    if (it == targets_.end()) {
        auto bad = unmadeTargets_.find(slot);
        throw Unsupported(bad != unmadeTargets_.end() ? bad->second : "probe of an undeclared render target");
    }
    Texture& t = it->second;
    if (x < 0 || y < 0 || x >= t.desc.width || y >= t.desc.height) throw std::runtime_error("probe outside the render target");
    if (t.readback.empty()) readBack(t.texture.Get(), t.desc, t.readback);  // once per target after each draw
    return texelAt(t.readback, t.desc, t.desc.width, x, y);
}

Texel D3d11Session::readUav(int slot, int x, int y) {
    auto it = uavs_.find(slot);
    if (it == uavs_.end()) {
        auto bad = unmadeUavs_.find(slot);
        throw Unsupported(bad != unmadeUavs_.end() ? bad->second : "probe of an undeclared UAV");
    }
    Uav& u = it->second;
    if (u.readback.empty()) readBack(u.resource.Get(), u.desc, u.readback);
    if (!isBuffer(u.desc)) {
        if (x < 0 || y < 0 || x >= u.desc.width || y >= u.desc.height) throw std::runtime_error("probe outside the UAV texture");
        return texelAt(u.readback, u.desc, u.desc.width, x, y);
    }
    const std::size_t wordsPerElement = elementBytes(u.desc) / 4;
    if (x < 0 || x >= u.desc.width) throw std::runtime_error("probe outside the UAV buffer");
    Texel t;
    for (std::size_t k = 0; k < 4 && std::size_t(x) * wordsPerElement + k < u.readback.size(); ++k)
        t.bits[k] = u.readback[std::size_t(x) * wordsPerElement + k];
    return t;
}

}  // namespace conformance
