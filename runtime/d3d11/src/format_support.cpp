// ID3D11Device's questions about what it can do: CheckFormatSupport, CheckMultisampleQualityLevels
// and CheckFeatureSupport. The answers come from the same tables the resources are made from
// (formats.cpp, vertex_formats.cpp, typeless_formats.cpp) and from the GL driver underneath (the
// compressed families are GL extensions; sample counts are the driver's), so a program that asks
// before it makes never sees a format it was told about refused.
#include <cstring>

#include "d3d11_impl.h"
#include "guarded.h"

namespace fxport::d3d11 {

namespace {

UINT textureSupport(GraphicsDevice& core, DXGI_FORMAT format) {
    SurfaceFormat surface;
    if (typelessColourStorage(format, surface))  // made as a 2D texture; its views name what it reads as
        return core.supportsTextureFormat(surface) ? D3D11_FORMAT_SUPPORT_TEXTURE2D | D3D11_FORMAT_SUPPORT_MIP | D3D11_FORMAT_SUPPORT_CPU_LOCKABLE : 0;
    if (!textureFormat(format, surface) || !core.supportsTextureFormat(surface)) return 0;
    UINT bits = D3D11_FORMAT_SUPPORT_TEXTURE2D | D3D11_FORMAT_SUPPORT_TEXTURE3D | D3D11_FORMAT_SUPPORT_TEXTURECUBE |
                D3D11_FORMAT_SUPPORT_SHADER_LOAD | D3D11_FORMAT_SUPPORT_MIP | D3D11_FORMAT_SUPPORT_CPU_LOCKABLE;
    if (!isIntegerFormat(surface)) bits |= D3D11_FORMAT_SUPPORT_SHADER_SAMPLE | D3D11_FORMAT_SUPPORT_SHADER_GATHER;
    if (isCompressedFormat(surface)) return bits;
    bits |= D3D11_FORMAT_SUPPORT_TEXTURE1D;  // CreateTexture1D takes the uncompressed colour formats
    if (core.supportsRenderTargetFormat(surface)) {
        bits |= D3D11_FORMAT_SUPPORT_RENDER_TARGET | D3D11_FORMAT_SUPPORT_MULTISAMPLE_RENDERTARGET | D3D11_FORMAT_SUPPORT_MULTISAMPLE_LOAD;
        if (!isIntegerFormat(surface))
            bits |= D3D11_FORMAT_SUPPORT_BLENDABLE | D3D11_FORMAT_SUPPORT_MIP_AUTOGEN | D3D11_FORMAT_SUPPORT_MULTISAMPLE_RESOLVE;
    }
    return bits;
}

UINT depthSupport(DXGI_FORMAT format) {
    DepthFormat depth;
    UINT bits = 0;
    if (depthFormat(format, depth)) bits |= D3D11_FORMAT_SUPPORT_TEXTURE2D | D3D11_FORMAT_SUPPORT_DEPTH_STENCIL;
    if (depthFamilyOf(format)) bits |= D3D11_FORMAT_SUPPORT_TEXTURE2D;  // a typeless shadow map
    for (DXGI_FORMAT typeless : {DXGI_FORMAT_R32_TYPELESS, DXGI_FORMAT_R24G8_TYPELESS, DXGI_FORMAT_R32G8X24_TYPELESS, DXGI_FORMAT_R16_TYPELESS})
        if (depthFamilyOf(typeless)->sampledView == format)  // its shader-resource view
            bits |= D3D11_FORMAT_SUPPORT_TEXTURE2D | D3D11_FORMAT_SUPPORT_SHADER_LOAD | D3D11_FORMAT_SUPPORT_SHADER_SAMPLE |
                    D3D11_FORMAT_SUPPORT_SHADER_SAMPLE_COMPARISON | D3D11_FORMAT_SUPPORT_SHADER_GATHER_COMPARISON;
    return bits;
}

UINT bufferSupport(DXGI_FORMAT format) {
    UINT bits = 0;
    VertexFormat vertex;
    if (vertexFormat(format, vertex)) bits |= D3D11_FORMAT_SUPPORT_BUFFER | D3D11_FORMAT_SUPPORT_IA_VERTEX_BUFFER;
    if (format == DXGI_FORMAT_R16_UINT || format == DXGI_FORMAT_R32_UINT) bits |= D3D11_FORMAT_SUPPORT_BUFFER | D3D11_FORMAT_SUPPORT_IA_INDEX_BUFFER;
    return bits;
}

// D3D's answer to a structure of the wrong size (or none).
HRESULT wrongSize(const char* feature, std::size_t wanted, const void* out, UINT size) {
    return fail(E_INVALIDARG, std::string("CheckFeatureSupport: ") + feature + " needs a " + std::to_string(wanted) + "-byte structure (got " +
                                  std::to_string(size) + (out ? " bytes)" : " bytes and a null pointer)"));
}

// Copies a feature's answer when the caller's size is the structure's.
template <class T> HRESULT answer(const char* feature, void* out, UINT size, const T& value) {
    if (!out || size != sizeof(T)) return wrongSize(feature, sizeof(T), out, size);
    std::memcpy(out, &value, sizeof(T));
    return succeed();
}

}  // namespace

HRESULT Device::CheckFormatSupport(DXGI_FORMAT Format, UINT* pFormatSupport) {
    if (!pFormatSupport) return fail(E_INVALIDARG, "CheckFormatSupport: pFormatSupport is null");
    *pFormatSupport = 0;
    return guarded("CheckFormatSupport", [&] {
        *pFormatSupport = textureSupport(core(), Format) | depthSupport(Format) | bufferSupport(Format);
        if (*pFormatSupport == 0) return fail(E_FAIL, std::string("CheckFormatSupport: ") + formatName(Format) + " is not a format fxport makes");
        return succeed();
    });
}

HRESULT Device::CheckMultisampleQualityLevels(DXGI_FORMAT Format, UINT SampleCount, UINT* pNumQualityLevels) {
    if (!pNumQualityLevels) return fail(E_INVALIDARG, "CheckMultisampleQualityLevels: pNumQualityLevels is null");
    *pNumQualityLevels = 0;
    if (SampleCount == 0 || SampleCount > 32 || (SampleCount & (SampleCount - 1)) != 0)
        return fail(E_FAIL, "CheckMultisampleQualityLevels: SampleCount = " + std::to_string(SampleCount) + " (1, 2, 4, 8, 16 or 32)");
    return guarded("CheckMultisampleQualityLevels", [&] {
        const UINT bits = textureSupport(core(), Format);
        if (SampleCount == 1) *pNumQualityLevels = (bits | depthSupport(Format)) != 0 ? 1 : 0;
        // Multisampled textures are colour targets and depth-stencil buffers (CreateTexture2D).
        else if ((bits & D3D11_FORMAT_SUPPORT_MULTISAMPLE_RENDERTARGET || depthSupport(Format) & D3D11_FORMAT_SUPPORT_DEPTH_STENCIL) &&
                 int(SampleCount) <= core().maxSampleCount())
            *pNumQualityLevels = 1;
        return succeed();
    });
}

HRESULT Device::CheckFeatureSupport(D3D11_FEATURE Feature, void* pFeatureSupportData, UINT FeatureSupportDataSize) {
    void* out = pFeatureSupportData;
    const UINT size = FeatureSupportDataSize;
    switch (Feature) {
    case D3D11_FEATURE_THREADING:  // deferred contexts record on the program's thread; creation is not free-threaded
        return answer("D3D11_FEATURE_THREADING", out, size, D3D11_FEATURE_DATA_THREADING{FALSE, FALSE});
    case D3D11_FEATURE_DOUBLES:  // GL 4.0's doubles carry HLSL's double
        return answer("D3D11_FEATURE_DOUBLES", out, size, D3D11_FEATURE_DATA_DOUBLES{TRUE});
    case D3D11_FEATURE_D3D10_X_HARDWARE_OPTIONS:
        return answer("D3D11_FEATURE_D3D10_X_HARDWARE_OPTIONS", out, size, D3D11_FEATURE_DATA_D3D10_X_HARDWARE_OPTIONS{TRUE});
    case D3D11_FEATURE_ARCHITECTURE_INFO:
        return answer("D3D11_FEATURE_ARCHITECTURE_INFO", out, size, D3D11_FEATURE_DATA_ARCHITECTURE_INFO{FALSE});
    case D3D11_FEATURE_SHADER_MIN_PRECISION_SUPPORT:  // min16float and friends compute at full precision
        return answer("D3D11_FEATURE_SHADER_MIN_PRECISION_SUPPORT", out, size, D3D11_FEATURE_DATA_SHADER_MIN_PRECISION_SUPPORT{0, 0});
    case D3D11_FEATURE_FORMAT_SUPPORT: {
        if (!out || size != sizeof(D3D11_FEATURE_DATA_FORMAT_SUPPORT))
            return wrongSize("D3D11_FEATURE_FORMAT_SUPPORT", sizeof(D3D11_FEATURE_DATA_FORMAT_SUPPORT), out, size);
        auto* data = static_cast<D3D11_FEATURE_DATA_FORMAT_SUPPORT*>(out);
        return CheckFormatSupport(data->InFormat, &data->OutFormatSupport);
    }
    default:
        return fail(E_INVALIDARG, "CheckFeatureSupport: Feature = " + std::to_string(Feature) +
                                      " (fxport answers THREADING, DOUBLES, FORMAT_SUPPORT, D3D10_X_HARDWARE_OPTIONS, ARCHITECTURE_INFO and "
                                      "SHADER_MIN_PRECISION_SUPPORT)");
    }
}

}  // namespace fxport::d3d11
