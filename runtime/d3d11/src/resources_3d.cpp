// 3D textures: CreateTexture3D and their shader-resource views (D3D11_SRV_DIMENSION_TEXTURE3D).
// fxport's volumes are what shaders sample: BIND_SHADER_RESOURCE, USAGE_DEFAULT or IMMUTABLE, one
// level or the full chain; a view sees every level. Each level is one subresource, slices front to
// back (SysMemSlicePitch apart), rows SysMemPitch apart, as D3D lays it out.
#include <algorithm>
#include <cstring>

#include "d3d11_impl.h"
#include "guarded.h"

namespace fxport::d3d11 {

namespace {

constexpr UINT kMaxVolumeSize = 2048;  // D3D11_REQ_TEXTURE3D_U_V_OR_W_DIMENSION

int fullVolumeMipCount(const D3D11_TEXTURE3D_DESC& d) {
    int levels = 1;
    for (UINT size = std::max({d.Width, d.Height, d.Depth}); size > 1; size >>= 1) ++levels;
    return levels;
}

HRESULT checkVolumeDesc(const D3D11_TEXTURE3D_DESC& d, bool hasData, SurfaceFormat& format) {
    const std::string at = "CreateTexture3D: D3D11_TEXTURE3D_DESC.";
    if (d.Width == 0 || d.Height == 0 || d.Depth == 0 || d.Width > kMaxVolumeSize || d.Height > kMaxVolumeSize || d.Depth > kMaxVolumeSize)
        return fail(E_INVALIDARG, at + "Width x Height x Depth = " + std::to_string(d.Width) + " x " + std::to_string(d.Height) + " x " +
                                      std::to_string(d.Depth) + " (1 to 2048 each)");
    const int full = fullVolumeMipCount(d);
    if (int(d.MipLevels) > full)
        return fail(E_INVALIDARG, at + "MipLevels = " + std::to_string(d.MipLevels) + " (this volume has at most " + std::to_string(full) + ")");
    if (d.MipLevels != 0 && d.MipLevels != 1 && int(d.MipLevels) != full)
        return fail(E_NOTIMPL, at + "MipLevels = " + std::to_string(d.MipLevels) + ": fxport makes 1 level or the full chain (0 or " +
                                   std::to_string(full) + ")");
    if (d.BindFlags != D3D11_BIND_SHADER_RESOURCE)
        return fail(E_NOTIMPL, at + "BindFlags = " + std::to_string(d.BindFlags) + ": fxport's 3D textures are shader resources only (D3D11_BIND_SHADER_RESOURCE)");
    if (d.Usage == D3D11_USAGE_IMMUTABLE && !hasData) return fail(E_INVALIDARG, at + "Usage = D3D11_USAGE_IMMUTABLE without pInitialData");
    if (d.Usage != D3D11_USAGE_DEFAULT && d.Usage != D3D11_USAGE_IMMUTABLE)
        return fail(E_NOTIMPL, at + "Usage = " + std::to_string(d.Usage) + ": fxport's 3D textures are USAGE_DEFAULT or USAGE_IMMUTABLE");
    if (d.CPUAccessFlags) return fail(E_INVALIDARG, at + "CPUAccessFlags = " + std::to_string(d.CPUAccessFlags) + " with USAGE_DEFAULT or IMMUTABLE");
    if (d.MiscFlags) return fail(E_NOTIMPL, at + "MiscFlags = " + std::to_string(d.MiscFlags) + ": 3D textures take none in fxport");
    if (!textureFormat(d.Format, format) || depthFamilyOf(d.Format))
        return fail(d.Format == DXGI_FORMAT_UNKNOWN ? E_INVALIDARG : E_NOTIMPL,
                    at + "Format = " + formatName(d.Format) + " (" + std::to_string(d.Format) + "): not a texture format fxport supports (docs/API.md lists them)");
    return S_OK;
}

// Level `level` of `initial`, packed tightly (rows and slices without the caller's pitches).
HRESULT packLevel(const D3D11_SUBRESOURCE_DATA& s, int level, std::size_t row, int height, int depth, std::vector<std::uint8_t>& packed) {
    const std::string at = "CreateTexture3D: pInitialData[" + std::to_string(level) + "].";
    if (!s.pSysMem) return fail(E_INVALIDARG, at + "pSysMem is null");
    if (s.SysMemPitch < row)
        return fail(E_INVALIDARG, at + "SysMemPitch = " + std::to_string(s.SysMemPitch) + ", less than a row (" + std::to_string(row) + " bytes)");
    if (depth > 1 && s.SysMemSlicePitch < std::size_t(s.SysMemPitch) * std::size_t(height - 1) + row)
        return fail(E_INVALIDARG, at + "SysMemSlicePitch = " + std::to_string(s.SysMemSlicePitch) + ", less than a slice (" + std::to_string(height) +
                                      " rows of " + std::to_string(s.SysMemPitch) + " bytes)");
    packed.resize(row * std::size_t(height) * std::size_t(depth));
    const auto* source = static_cast<const std::uint8_t*>(s.pSysMem);
    for (int z = 0; z < depth; ++z)
        for (int y = 0; y < height; ++y)
            std::memcpy(&packed[(std::size_t(z) * std::size_t(height) + std::size_t(y)) * row],
                        source + std::size_t(z) * s.SysMemSlicePitch + std::size_t(y) * s.SysMemPitch, row);
    return S_OK;
}

}  // namespace

HRESULT Device::CreateTexture3D(const D3D11_TEXTURE3D_DESC* pDesc, const D3D11_SUBRESOURCE_DATA* pInitialData, ID3D11Texture3D** ppTexture3D) {
    const char* call = "CreateTexture3D";
    if (!pDesc) return fail(E_INVALIDARG, "CreateTexture3D: pDesc is null");
    const D3D11_TEXTURE3D_DESC& d = *pDesc;
    SurfaceFormat format = SurfaceFormat::Color;
    if (HRESULT hr = checkVolumeDesc(d, pInitialData != nullptr, format); FAILED(hr)) return hr;
    if (!ppTexture3D) return succeed();  // D3D: validation only
    return guarded(call, [&] {
        auto volume = std::unique_ptr<Volume, void (*)(Volume*)>(new Volume(this, d), [](Volume* v) { v->Release(); });
        const int full = fullVolumeMipCount(d);
        volume->texels = std::make_unique<fxport::Texture3D>(core(), int(d.Width), int(d.Height), int(d.Depth), d.MipLevels != 1, format);
        volume->desc.MipLevels = UINT(d.MipLevels == 1 ? 1 : full);
        if (pInitialData) {
            std::vector<std::uint8_t> packed;
            for (int level = 0; level < int(volume->desc.MipLevels); ++level) {
                const int w = std::max(1, int(d.Width) >> level), h = std::max(1, int(d.Height) >> level), z = std::max(1, int(d.Depth) >> level);
                const std::size_t row = rowBytes(format, w);  // of 4x4 blocks for BC formats
                if (HRESULT hr = packLevel(pInitialData[level], level, row, rowCount(format, h), z, packed); FAILED(hr)) return hr;
                volume->texels->setData(level, packed.data(), packed.size());
            }
        }
        *ppTexture3D = volume.release();
        return succeed();
    });
}

HRESULT volumeShaderResourceView(Device* device, Volume* v, const D3D11_SHADER_RESOURCE_VIEW_DESC* pDesc, ID3D11ShaderResourceView** pp) {
    const std::string call = "CreateShaderResourceView";
    D3D11_SHADER_RESOURCE_VIEW_DESC d;
    d.Format = v->desc.Format;
    d.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE3D;
    d.Texture3D.MipLevels = v->desc.MipLevels;
    if (pDesc) {
        if (pDesc->ViewDimension != D3D11_SRV_DIMENSION_TEXTURE3D)
            return fail(E_INVALIDARG, call + ": D3D11_SHADER_RESOURCE_VIEW_DESC.ViewDimension = " + std::to_string(pDesc->ViewDimension) +
                                          " for a 3D texture (D3D11_SRV_DIMENSION_TEXTURE3D)");
        if (pDesc->Format != DXGI_FORMAT_UNKNOWN && pDesc->Format != v->desc.Format)
            return fail(E_NOTIMPL, call + ": D3D11_SHADER_RESOURCE_VIEW_DESC.Format = " + formatName(pDesc->Format) + " for a " +
                                       formatName(v->desc.Format) + " 3D texture: fxport views it in its own format");
        const UINT first = pDesc->Texture3D.MostDetailedMip, levels = pDesc->Texture3D.MipLevels;
        if (first != 0 || (levels != UINT(-1) && levels != v->desc.MipLevels))
            return fail(E_NOTIMPL, call + ": D3D11_SHADER_RESOURCE_VIEW_DESC.Texture3D = {MostDetailedMip " + std::to_string(first) + ", MipLevels " +
                                       std::to_string(levels) + "}: fxport views every level (0, -1)");
    }
    if (!pp) return succeed();
    *pp = new ShaderResourceView(device, v, d);
    return succeed();
}

}  // namespace fxport::d3d11
