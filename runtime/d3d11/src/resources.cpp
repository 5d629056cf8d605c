// Buffers and 2D textures: CreateBuffer, CreateTexture2D and their checks (multisampled ones'
// in resources_multisample.cpp). A D3D buffer is one
// device-core byte buffer whatever it is bound as; a texture is a Texture2D (a RenderTarget2D when
// it may be rendered to), a depth buffer (BIND_DEPTH_STENCIL), or CPU memory (USAGE_STAGING, which
// CopyResource and Map read and write, as D3D's staging resources are).
#include <algorithm>
#include <cstring>

#include "d3d11_impl.h"
#include "device/multisample_target.h"
#include "guarded.h"

namespace fxport::d3d11 {

int fullMipCount(UINT w, UINT h) {
    int levels = 1;
    for (UINT size = std::max(w, h); size > 1; size >>= 1) ++levels;
    return levels;
}

HRESULT checkUsage(const char* call, const char* desc, D3D11_USAGE usage, UINT bind, UINT cpu, bool hasData) {
    const std::string at = std::string(call) + ": " + desc;
    switch (usage) {
    case D3D11_USAGE_DEFAULT:
        if (cpu) return fail(E_INVALIDARG, at + ".CPUAccessFlags = " + std::to_string(cpu) + " with USAGE_DEFAULT (CPU access needs DYNAMIC or STAGING)");
        return S_OK;
    case D3D11_USAGE_IMMUTABLE:
        if (!hasData) return fail(E_INVALIDARG, at + ".Usage = D3D11_USAGE_IMMUTABLE without pInitialData");
        if (cpu) return fail(E_INVALIDARG, at + ".CPUAccessFlags = " + std::to_string(cpu) + " with USAGE_IMMUTABLE");
        return S_OK;
    case D3D11_USAGE_DYNAMIC:
        if (cpu != D3D11_CPU_ACCESS_WRITE)
            return fail(E_INVALIDARG, at + ".CPUAccessFlags = " + std::to_string(cpu) + " with USAGE_DYNAMIC (must be D3D11_CPU_ACCESS_WRITE)");
        return S_OK;
    case D3D11_USAGE_STAGING:
        if (bind) return fail(E_INVALIDARG, at + ".BindFlags = " + std::to_string(bind) + " with USAGE_STAGING (must be 0)");
        if (!cpu) return fail(E_INVALIDARG, at + ".CPUAccessFlags = 0 with USAGE_STAGING (needs READ and/or WRITE)");
        return S_OK;
    }
    return fail(E_INVALIDARG, at + ".Usage = " + std::to_string(usage) + " is not a D3D11_USAGE value (0-3)");
}

namespace {

// D3D's rules for structured and raw buffers (MiscFlags, StructureByteStride) and for buffers a
// shader writes (BIND_UNORDERED_ACCESS).
HRESULT checkBufferMisc(const D3D11_BUFFER_DESC& d) {
    const std::string at = "CreateBuffer: D3D11_BUFFER_DESC.";
    const UINT misc = D3D11_RESOURCE_MISC_BUFFER_STRUCTURED | D3D11_RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS;
    if (d.MiscFlags & ~misc)
        return fail(E_NOTIMPL, at + "MiscFlags = " + std::to_string(d.MiscFlags) + ": buffers take BUFFER_STRUCTURED and BUFFER_ALLOW_RAW_VIEWS only");
    const bool structured = (d.MiscFlags & D3D11_RESOURCE_MISC_BUFFER_STRUCTURED) != 0;
    const bool raw = (d.MiscFlags & D3D11_RESOURCE_MISC_BUFFER_ALLOW_RAW_VIEWS) != 0;
    if (structured && raw) return fail(E_INVALIDARG, at + "MiscFlags = " + std::to_string(d.MiscFlags) + ": a buffer is structured or raw, not both");
    if (structured) {
        if (d.StructureByteStride == 0 || d.StructureByteStride % 4 != 0 || d.StructureByteStride > 2048)
            return fail(E_INVALIDARG, at + "StructureByteStride = " + std::to_string(d.StructureByteStride) +
                                          " for a structured buffer (a multiple of 4, 4 to 2048)");
        if (d.ByteWidth % d.StructureByteStride != 0)
            return fail(E_INVALIDARG, at + "ByteWidth = " + std::to_string(d.ByteWidth) + " is not a multiple of StructureByteStride = " +
                                          std::to_string(d.StructureByteStride));
        const UINT ia = D3D11_BIND_VERTEX_BUFFER | D3D11_BIND_INDEX_BUFFER | D3D11_BIND_CONSTANT_BUFFER;
        if (d.BindFlags & ia)
            return fail(E_INVALIDARG, at + "BindFlags = " + std::to_string(d.BindFlags) + ": a structured buffer cannot be a vertex, index or constant buffer");
    }
    if (raw && d.ByteWidth % 4 != 0)
        return fail(E_INVALIDARG, at + "ByteWidth = " + std::to_string(d.ByteWidth) + " for a raw buffer (a multiple of 4)");
    if ((d.BindFlags & D3D11_BIND_UNORDERED_ACCESS) && (d.Usage == D3D11_USAGE_DYNAMIC || d.Usage == D3D11_USAGE_IMMUTABLE))
        return fail(E_INVALIDARG, at + "Usage = " + std::to_string(d.Usage) + " with BIND_UNORDERED_ACCESS (a buffer a shader writes is USAGE_DEFAULT)");
    return S_OK;
}

// D3D's cube textures: MISC_TEXTURECUBE and six square faces (ArraySize 6, in D3D's face order,
// which is XNA's CubeMapFace order). fxport samples them: BIND_SHADER_RESOURCE only, one level.
HRESULT checkCube(const D3D11_TEXTURE2D_DESC& d, const std::string& at) {
    if (d.ArraySize % 6 != 0 || d.Width != d.Height)
        return fail(E_INVALIDARG, at + "ArraySize = " + std::to_string(d.ArraySize) + ", Width x Height = " + std::to_string(d.Width) + " x " +
                                      std::to_string(d.Height) + " with D3D11_RESOURCE_MISC_TEXTURECUBE (a cube is six square faces)");
    if (d.BindFlags != D3D11_BIND_SHADER_RESOURCE || (d.Usage != D3D11_USAGE_DEFAULT && d.Usage != D3D11_USAGE_IMMUTABLE))
        return fail(E_NOTIMPL, at + "BindFlags = " + std::to_string(d.BindFlags) + ", Usage = " + std::to_string(d.Usage) +
                                   " for a cube texture: fxport's cube textures are DEFAULT or IMMUTABLE shader resources only");
    if (d.MipLevels != 1)
        return fail(E_NOTIMPL, at + "MipLevels = " + std::to_string(d.MipLevels) + " for a cube texture: fxport makes one level");
    return S_OK;
}

}  // namespace

// --- Buffer

Buffer::Buffer(Device* device, const D3D11_BUFFER_DESC& d, const void* initial) : Object(device), desc(d) {
    if (d.Usage == D3D11_USAGE_STAGING) {
        cpu.assign(d.ByteWidth, 0);
        if (initial) std::memcpy(cpu.data(), initial, d.ByteWidth);
    } else {
        gpu = std::make_unique<core::ByteBuffer>(device->core(), d.ByteWidth, initial, d.Usage == D3D11_USAGE_DYNAMIC);
    }
}

HRESULT Device::CreateBuffer(const D3D11_BUFFER_DESC* pDesc, const D3D11_SUBRESOURCE_DATA* pInitialData, ID3D11Buffer** ppBuffer) {
    const char* call = "CreateBuffer";
    if (!pDesc) return fail(E_INVALIDARG, "CreateBuffer: pDesc is null");
    const D3D11_BUFFER_DESC& d = *pDesc;
    if (d.ByteWidth == 0) return fail(E_INVALIDARG, "CreateBuffer: D3D11_BUFFER_DESC.ByteWidth = 0");
    if (d.BindFlags & D3D11_BIND_CONSTANT_BUFFER) {
        if (d.ByteWidth % 16 != 0)
            return fail(E_INVALIDARG, "CreateBuffer: D3D11_BUFFER_DESC.ByteWidth = " + std::to_string(d.ByteWidth) +
                                          " for a constant buffer (must be a multiple of 16)");
        if (d.BindFlags != D3D11_BIND_CONSTANT_BUFFER)
            return fail(E_INVALIDARG, "CreateBuffer: D3D11_BUFFER_DESC.BindFlags = " + std::to_string(d.BindFlags) +
                                          " (D3D11_BIND_CONSTANT_BUFFER may not be combined with other flags)");
        if (d.ByteWidth > 65536)
            return fail(E_INVALIDARG, "CreateBuffer: D3D11_BUFFER_DESC.ByteWidth = " + std::to_string(d.ByteWidth) +
                                          " for a constant buffer (at most 4096 registers, 65536 bytes)");
    }
    const UINT known = D3D11_BIND_VERTEX_BUFFER | D3D11_BIND_INDEX_BUFFER | D3D11_BIND_CONSTANT_BUFFER | D3D11_BIND_SHADER_RESOURCE |
                       D3D11_BIND_UNORDERED_ACCESS | D3D11_BIND_STREAM_OUTPUT;
    if (d.BindFlags & ~known)
        return fail(E_NOTIMPL, "CreateBuffer: D3D11_BUFFER_DESC.BindFlags = " + std::to_string(d.BindFlags) +
                                   ": fxport binds buffers as vertex, index, constant, shader-resource, unordered-access and stream-output buffers");
    if ((d.BindFlags & D3D11_BIND_STREAM_OUTPUT) && d.Usage != D3D11_USAGE_DEFAULT)
        return fail(E_INVALIDARG, "CreateBuffer: a stream-output buffer (D3D11_BIND_STREAM_OUTPUT) has D3D11_USAGE_DEFAULT");
    if (HRESULT hr = checkBufferMisc(d); FAILED(hr)) return hr;
    if (HRESULT hr = checkUsage(call, "D3D11_BUFFER_DESC", d.Usage, d.BindFlags, d.CPUAccessFlags, pInitialData && pInitialData->pSysMem); FAILED(hr))
        return hr;
    if (pInitialData && !pInitialData->pSysMem) return fail(E_INVALIDARG, "CreateBuffer: pInitialData->pSysMem is null");
    if (!ppBuffer) return succeed();  // D3D: validation only
    return guarded(call, [&] {
        *ppBuffer = new Buffer(this, d, pInitialData ? pInitialData->pSysMem : nullptr);
        return succeed();
    });
}

// --- Texture2D

Texture::Texture(Device* device, const D3D11_TEXTURE2D_DESC& d) : Object(device), desc(d) {}

std::size_t Texture::levelBytes(int level) const {
    return regionBytes(format, levelWidth(level), levelHeight(level));
}

HRESULT Device::CreateTexture2D(const D3D11_TEXTURE2D_DESC* pDesc, const D3D11_SUBRESOURCE_DATA* pInitialData,
                                ID3D11Texture2D** ppTexture2D) {
    const char* call = "CreateTexture2D";
    if (!pDesc) return fail(E_INVALIDARG, "CreateTexture2D: pDesc is null");
    const D3D11_TEXTURE2D_DESC& d = *pDesc;
    const std::string at = "CreateTexture2D: D3D11_TEXTURE2D_DESC.";
    if (d.Width == 0 || d.Height == 0 || d.Width > 16384 || d.Height > 16384)
        return fail(E_INVALIDARG, at + "Width x Height = " + std::to_string(d.Width) + " x " + std::to_string(d.Height) + " (1 to 16384 each)");
    if (d.ArraySize == 0) return fail(E_INVALIDARG, at + "ArraySize = 0");
    const bool isCube = (d.MiscFlags & D3D11_RESOURCE_MISC_TEXTURECUBE) != 0;
    if (d.ArraySize > 1 && !isCube) return createTextureArray(this, d, pInitialData, ppTexture2D);
    if (isCube && d.ArraySize > 6) return createTextureArray(this, d, pInitialData, ppTexture2D);  // a cube array
    if (d.SampleDesc.Count == 0) return fail(E_INVALIDARG, at + "SampleDesc.Count = 0");
    if (d.SampleDesc.Count > 1)
        if (HRESULT hr = checkMultisampleDesc(d, pInitialData != nullptr); FAILED(hr)) return hr;
    if (d.MiscFlags & ~UINT(D3D11_RESOURCE_MISC_GENERATE_MIPS | D3D11_RESOURCE_MISC_TEXTURECUBE))
        return fail(E_NOTIMPL, at + "MiscFlags = " + std::to_string(d.MiscFlags) + ": only D3D11_RESOURCE_MISC_GENERATE_MIPS and TEXTURECUBE are supported");
    if (isCube)
        if (HRESULT hr = checkCube(d, at); FAILED(hr)) return hr;
    const int full = fullMipCount(d.Width, d.Height);
    if (int(d.MipLevels) > full)
        return fail(E_INVALIDARG, at + "MipLevels = " + std::to_string(d.MipLevels) + " (a " + std::to_string(d.Width) + "x" +
                                      std::to_string(d.Height) + " texture has at most " + std::to_string(full) + ")");
    if (d.MipLevels != 0 && d.MipLevels != 1 && int(d.MipLevels) != full)
        return fail(E_NOTIMPL, at + "MipLevels = " + std::to_string(d.MipLevels) + ": fxport makes 1 level or the full chain (0 or " +
                                   std::to_string(full) + ")");
    const UINT known = D3D11_BIND_SHADER_RESOURCE | D3D11_BIND_RENDER_TARGET | D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_UNORDERED_ACCESS;
    if (d.BindFlags & ~known)
        return fail(E_NOTIMPL, at + "BindFlags = " + std::to_string(d.BindFlags) + ": only SHADER_RESOURCE, RENDER_TARGET, DEPTH_STENCIL and UNORDERED_ACCESS");
    if ((d.BindFlags & D3D11_BIND_UNORDERED_ACCESS) && d.Usage != D3D11_USAGE_DEFAULT)
        return fail(E_INVALIDARG, at + "Usage = " + std::to_string(d.Usage) + " with BIND_UNORDERED_ACCESS (must be USAGE_DEFAULT)");
    const bool depthTarget = (d.BindFlags & D3D11_BIND_DEPTH_STENCIL) != 0;
    const DepthFamily* family = depthFamilyOf(d.Format);
    if (depthTarget && (d.BindFlags & D3D11_BIND_RENDER_TARGET))
        return fail(E_INVALIDARG, at + "BindFlags = " + std::to_string(d.BindFlags) + ": a texture is a depth-stencil or a render target, not both");
    if (depthTarget && (d.BindFlags & D3D11_BIND_SHADER_RESOURCE) && !family)
        return fail(E_INVALIDARG, at + "BindFlags = " + std::to_string(d.BindFlags) + " with Format = " + formatName(d.Format) +
                                      ": a depth texture a shader samples is made typeless (R32_TYPELESS, R24G8_TYPELESS, R16_TYPELESS)");
    if (family && (d.BindFlags & (D3D11_BIND_RENDER_TARGET | D3D11_BIND_UNORDERED_ACCESS)))
        return fail(E_NOTIMPL, at + "BindFlags = " + std::to_string(d.BindFlags) + " with Format = " + formatName(d.Format) +
                                   ": fxport keeps a typeless texture as a depth texture (DEPTH_STENCIL and SHADER_RESOURCE only)");
    const bool sampledDepth = family && (d.BindFlags & D3D11_BIND_SHADER_RESOURCE);
    if (sampledDepth && depthTarget && d.MipLevels != 1)
        return fail(E_NOTIMPL, at + "MipLevels = " + std::to_string(d.MipLevels) + " for a depth texture: fxport makes 1 level");
    if (family && hasStencil(family->depth) && pInitialData)
        return fail(E_NOTIMPL, at + "Format = " + formatName(d.Format) + " with pInitialData: fxport does not upload packed depth-stencil texels");
    if (HRESULT hr = checkUsage(call, "D3D11_TEXTURE2D_DESC", d.Usage, d.BindFlags, d.CPUAccessFlags, pInitialData && pInitialData->pSysMem); FAILED(hr))
        return hr;
    SurfaceFormat surface = family ? family->sampled : SurfaceFormat::Color;
    DepthFormat depth = family ? family->depth : DepthFormat::None;
    if (!family && (depthTarget ? !depthFormat(d.Format, depth) : !textureFormat(d.Format, surface) && !typelessColourStorage(d.Format, surface)))
        return fail(d.Format == DXGI_FORMAT_UNKNOWN ? E_INVALIDARG : E_NOTIMPL, at + "Format = " + formatName(d.Format) + " (" + std::to_string(d.Format) +
                                                             "): not a " + (depthTarget ? "depth" : "texture") +
                                                             " format fxport supports (docs/API.md lists them)");
    if (depthTarget && pInitialData) return fail(E_INVALIDARG, at + "BindFlags has DEPTH_STENCIL and pInitialData is given");
    if (HRESULT hr = checkCompressedUse(at, d, surface); FAILED(hr)) return hr;
    if ((d.MiscFlags & D3D11_RESOURCE_MISC_GENERATE_MIPS) && !depthTarget && isIntegerFormat(surface))
        return fail(E_INVALIDARG, at + "MiscFlags = " + std::to_string(d.MiscFlags) + " (D3D11_RESOURCE_MISC_GENERATE_MIPS) with Format = " +
                                      formatName(d.Format) + ": integer texels cannot be filtered into smaller levels");
    if (!ppTexture2D) return succeed();
    return guarded(call, [&] {
        auto texture = std::unique_ptr<Texture, void (*)(Texture*)>(new Texture(this, d), [](Texture* t) { t->Release(); });
        Texture& t = *texture;
        t.format = surface;
        t.levels = d.MipLevels == 1 ? 1 : full;
        t.desc.MipLevels = UINT(t.levels);
        const bool mips = t.levels > 1;
        if (depthTarget && sampledDepth) {  // a shadow map: one depth texture under its DSV and SRV
            t.colour = std::make_unique<fxport::Texture2D>(core(), int(d.Width), int(d.Height), false, surface);
            t.depth = std::make_unique<core::DepthBuffer>(core(), *t.colour);
        } else if (depthTarget) {
            const int samples = d.SampleDesc.Count > 1 ? int(d.SampleDesc.Count) : 0;
            t.depth = std::make_unique<core::DepthBuffer>(core(), int(d.Width), int(d.Height), depth, samples);
        } else if (d.SampleDesc.Count > 1) {
            t.colour = std::make_unique<core::MultisampleTarget>(core(), int(d.Width), int(d.Height), surface, int(d.SampleDesc.Count));
        } else if (isCube) {
            t.cube = std::make_unique<fxport::TextureCube>(core(), int(d.Width), false, surface);
        } else if (d.Usage == D3D11_USAGE_STAGING) {
            for (int level = 0; level < t.levels; ++level) t.staging.emplace_back(t.levelBytes(level), 0);
        } else if (d.BindFlags & D3D11_BIND_RENDER_TARGET) {
            t.colour = std::make_unique<RenderTarget2D>(core(), int(d.Width), int(d.Height), mips, surface, DepthFormat::None, 0,
                                                        RenderTargetUsage::PreserveContents);
        } else {
            t.colour = std::make_unique<fxport::Texture2D>(core(), int(d.Width), int(d.Height), mips, surface);
        }
        if (pInitialData) {
            // Subresource face * levels + level (a 2D texture has one face).
            for (int sub = 0; sub < (isCube ? 6 : 1) * t.levels; ++sub) {
                const int level = sub % t.levels, face = sub / t.levels;
                const D3D11_SUBRESOURCE_DATA& s = pInitialData[sub];
                if (!s.pSysMem) return fail(E_INVALIDARG, "CreateTexture2D: pInitialData[" + std::to_string(sub) + "].pSysMem is null");
                const std::size_t row = rowBytes(surface, t.levelWidth(level));  // of 4x4 blocks for BC formats
                if (s.SysMemPitch < row)
                    return fail(E_INVALIDARG, "CreateTexture2D: pInitialData[" + std::to_string(sub) + "].SysMemPitch = " +
                                                  std::to_string(s.SysMemPitch) + ", less than a row (" + std::to_string(row) + " bytes)");
                std::vector<std::uint8_t> packed(t.levelBytes(level));
                for (int y = 0; y < rowCount(surface, t.levelHeight(level)); ++y)
                    std::memcpy(&packed[std::size_t(y) * row], static_cast<const std::uint8_t*>(s.pSysMem) + std::size_t(y) * s.SysMemPitch, row);
                if (!t.staging.empty()) t.staging[std::size_t(level)] = std::move(packed);
                else if (t.cube) t.cube->setData(CubeMapFace(face), packed.data(), packed.size());
                else t.colour->setData(level, nullptr, packed.data(), packed.size());
            }
        }
        *ppTexture2D = texture.release();
        return succeed();
    });
}

}  // namespace fxport::d3d11
