// DXGI formats -> the device core's texture, depth and vertex formats (those it has): float,
// unorm, snorm, integer (UINT/SINT, unfiltered) and BGRA texels.
#include "d3d11_impl.h"

namespace fxport::d3d11 {

const char* formatName(DXGI_FORMAT f) {
    switch (f) {
    case DXGI_FORMAT_UNKNOWN: return "DXGI_FORMAT_UNKNOWN";
    case DXGI_FORMAT_R32G32B32A32_FLOAT: return "DXGI_FORMAT_R32G32B32A32_FLOAT";
    case DXGI_FORMAT_R32G32B32A32_UINT: return "DXGI_FORMAT_R32G32B32A32_UINT";
    case DXGI_FORMAT_R32G32B32A32_SINT: return "DXGI_FORMAT_R32G32B32A32_SINT";
    case DXGI_FORMAT_R32G32B32_FLOAT: return "DXGI_FORMAT_R32G32B32_FLOAT";
    case DXGI_FORMAT_R32G32B32_UINT: return "DXGI_FORMAT_R32G32B32_UINT";
    case DXGI_FORMAT_R32G32B32_SINT: return "DXGI_FORMAT_R32G32B32_SINT";
    case DXGI_FORMAT_R16G16B16A16_FLOAT: return "DXGI_FORMAT_R16G16B16A16_FLOAT";
    case DXGI_FORMAT_R16G16B16A16_UNORM: return "DXGI_FORMAT_R16G16B16A16_UNORM";
    case DXGI_FORMAT_R16G16B16A16_UINT: return "DXGI_FORMAT_R16G16B16A16_UINT";
    case DXGI_FORMAT_R16G16B16A16_SNORM: return "DXGI_FORMAT_R16G16B16A16_SNORM";
    case DXGI_FORMAT_R16G16B16A16_SINT: return "DXGI_FORMAT_R16G16B16A16_SINT";
    case DXGI_FORMAT_R32G32_FLOAT: return "DXGI_FORMAT_R32G32_FLOAT";
    case DXGI_FORMAT_R32G32_UINT: return "DXGI_FORMAT_R32G32_UINT";
    case DXGI_FORMAT_R32G32_SINT: return "DXGI_FORMAT_R32G32_SINT";
    case DXGI_FORMAT_R10G10B10A2_UNORM: return "DXGI_FORMAT_R10G10B10A2_UNORM";
    case DXGI_FORMAT_R10G10B10A2_UINT: return "DXGI_FORMAT_R10G10B10A2_UINT";
    case DXGI_FORMAT_R11G11B10_FLOAT: return "DXGI_FORMAT_R11G11B10_FLOAT";
    case DXGI_FORMAT_R8G8B8A8_TYPELESS: return "DXGI_FORMAT_R8G8B8A8_TYPELESS";
    case DXGI_FORMAT_R8G8B8A8_UNORM: return "DXGI_FORMAT_R8G8B8A8_UNORM";
    case DXGI_FORMAT_R8G8B8A8_UNORM_SRGB: return "DXGI_FORMAT_R8G8B8A8_UNORM_SRGB";
    case DXGI_FORMAT_R8G8B8A8_UINT: return "DXGI_FORMAT_R8G8B8A8_UINT";
    case DXGI_FORMAT_R8G8B8A8_SNORM: return "DXGI_FORMAT_R8G8B8A8_SNORM";
    case DXGI_FORMAT_R8G8B8A8_SINT: return "DXGI_FORMAT_R8G8B8A8_SINT";
    case DXGI_FORMAT_R16G16_FLOAT: return "DXGI_FORMAT_R16G16_FLOAT";
    case DXGI_FORMAT_R16G16_UNORM: return "DXGI_FORMAT_R16G16_UNORM";
    case DXGI_FORMAT_R16G16_UINT: return "DXGI_FORMAT_R16G16_UINT";
    case DXGI_FORMAT_R16G16_SNORM: return "DXGI_FORMAT_R16G16_SNORM";
    case DXGI_FORMAT_R16G16_SINT: return "DXGI_FORMAT_R16G16_SINT";
    case DXGI_FORMAT_R32_TYPELESS: return "DXGI_FORMAT_R32_TYPELESS";
    case DXGI_FORMAT_D32_FLOAT: return "DXGI_FORMAT_D32_FLOAT";
    case DXGI_FORMAT_R32_FLOAT: return "DXGI_FORMAT_R32_FLOAT";
    case DXGI_FORMAT_R32_UINT: return "DXGI_FORMAT_R32_UINT";
    case DXGI_FORMAT_R32_SINT: return "DXGI_FORMAT_R32_SINT";
    case DXGI_FORMAT_D24_UNORM_S8_UINT: return "DXGI_FORMAT_D24_UNORM_S8_UINT";
    case DXGI_FORMAT_R8G8_UNORM: return "DXGI_FORMAT_R8G8_UNORM";
    case DXGI_FORMAT_R8G8_UINT: return "DXGI_FORMAT_R8G8_UINT";
    case DXGI_FORMAT_R8G8_SNORM: return "DXGI_FORMAT_R8G8_SNORM";
    case DXGI_FORMAT_R8G8_SINT: return "DXGI_FORMAT_R8G8_SINT";
    case DXGI_FORMAT_R16_FLOAT: return "DXGI_FORMAT_R16_FLOAT";
    case DXGI_FORMAT_D16_UNORM: return "DXGI_FORMAT_D16_UNORM";
    case DXGI_FORMAT_R16_UNORM: return "DXGI_FORMAT_R16_UNORM";
    case DXGI_FORMAT_R16_UINT: return "DXGI_FORMAT_R16_UINT";
    case DXGI_FORMAT_R16_SNORM: return "DXGI_FORMAT_R16_SNORM";
    case DXGI_FORMAT_R16_SINT: return "DXGI_FORMAT_R16_SINT";
    case DXGI_FORMAT_R8_UNORM: return "DXGI_FORMAT_R8_UNORM";
    case DXGI_FORMAT_R8_UINT: return "DXGI_FORMAT_R8_UINT";
    case DXGI_FORMAT_R8_SNORM: return "DXGI_FORMAT_R8_SNORM";
    case DXGI_FORMAT_R8_SINT: return "DXGI_FORMAT_R8_SINT";
    case DXGI_FORMAT_A8_UNORM: return "DXGI_FORMAT_A8_UNORM";
    case DXGI_FORMAT_B8G8R8A8_UNORM: return "DXGI_FORMAT_B8G8R8A8_UNORM";
    case DXGI_FORMAT_R32G32B32A32_TYPELESS: return "DXGI_FORMAT_R32G32B32A32_TYPELESS";
    case DXGI_FORMAT_R16G16B16A16_TYPELESS: return "DXGI_FORMAT_R16G16B16A16_TYPELESS";
    case DXGI_FORMAT_R32G32_TYPELESS: return "DXGI_FORMAT_R32G32_TYPELESS";
    case DXGI_FORMAT_R16G16_TYPELESS: return "DXGI_FORMAT_R16G16_TYPELESS";
    case DXGI_FORMAT_R24G8_TYPELESS: return "DXGI_FORMAT_R24G8_TYPELESS";
    case DXGI_FORMAT_R24_UNORM_X8_TYPELESS: return "DXGI_FORMAT_R24_UNORM_X8_TYPELESS";
    case DXGI_FORMAT_X24_TYPELESS_G8_UINT: return "DXGI_FORMAT_X24_TYPELESS_G8_UINT";
    case DXGI_FORMAT_R8G8_TYPELESS: return "DXGI_FORMAT_R8G8_TYPELESS";
    case DXGI_FORMAT_R16_TYPELESS: return "DXGI_FORMAT_R16_TYPELESS";
    case DXGI_FORMAT_R8_TYPELESS: return "DXGI_FORMAT_R8_TYPELESS";
    case DXGI_FORMAT_B8G8R8A8_TYPELESS: return "DXGI_FORMAT_B8G8R8A8_TYPELESS";
    case DXGI_FORMAT_B8G8R8A8_UNORM_SRGB: return "DXGI_FORMAT_B8G8R8A8_UNORM_SRGB";
    }
    return "(a DXGI_FORMAT fxport does not know)";
}

bool textureFormat(DXGI_FORMAT f, SurfaceFormat& out) {
    switch (f) {
    case DXGI_FORMAT_R8G8B8A8_UNORM: out = SurfaceFormat::Color; return true;
    case DXGI_FORMAT_R8G8B8A8_UNORM_SRGB: out = SurfaceFormat::ColorSRgb; return true;
    case DXGI_FORMAT_R32G32B32A32_FLOAT: out = SurfaceFormat::Vector4; return true;
    case DXGI_FORMAT_R16G16B16A16_FLOAT: out = SurfaceFormat::HalfVector4; return true;
    case DXGI_FORMAT_R16G16B16A16_UNORM: out = SurfaceFormat::Rgba64; return true;
    case DXGI_FORMAT_R32G32_FLOAT: out = SurfaceFormat::Vector2; return true;
    case DXGI_FORMAT_R16G16_FLOAT: out = SurfaceFormat::HalfVector2; return true;
    case DXGI_FORMAT_R16G16_UNORM: out = SurfaceFormat::Rg32; return true;
    case DXGI_FORMAT_R32_FLOAT: out = SurfaceFormat::Single; return true;
    case DXGI_FORMAT_R16_FLOAT: out = SurfaceFormat::HalfSingle; return true;
    case DXGI_FORMAT_R10G10B10A2_UNORM: out = SurfaceFormat::Rgba1010102; return true;
    case DXGI_FORMAT_A8_UNORM: out = SurfaceFormat::Alpha8; return true;
    // D3D10+'s integer and BGRA formats (fxport additions to SurfaceFormat)
    case DXGI_FORMAT_R32_UINT: out = SurfaceFormat::R32UInt; return true;
    case DXGI_FORMAT_R32_SINT: out = SurfaceFormat::R32SInt; return true;
    case DXGI_FORMAT_R32G32_UINT: out = SurfaceFormat::Rg32UInt; return true;
    case DXGI_FORMAT_R32G32_SINT: out = SurfaceFormat::Rg32SInt; return true;
    case DXGI_FORMAT_R32G32B32A32_UINT: out = SurfaceFormat::Rgba32UInt; return true;
    case DXGI_FORMAT_R32G32B32A32_SINT: out = SurfaceFormat::Rgba32SInt; return true;
    case DXGI_FORMAT_R16_UINT: out = SurfaceFormat::R16UInt; return true;
    case DXGI_FORMAT_R16_SINT: out = SurfaceFormat::R16SInt; return true;
    case DXGI_FORMAT_R16G16_UINT: out = SurfaceFormat::Rg16UInt; return true;
    case DXGI_FORMAT_R16G16_SINT: out = SurfaceFormat::Rg16SInt; return true;
    case DXGI_FORMAT_R16G16B16A16_UINT: out = SurfaceFormat::Rgba16UInt; return true;
    case DXGI_FORMAT_R16G16B16A16_SINT: out = SurfaceFormat::Rgba16SInt; return true;
    case DXGI_FORMAT_R8_UINT: out = SurfaceFormat::R8UInt; return true;
    case DXGI_FORMAT_R8_SINT: out = SurfaceFormat::R8SInt; return true;
    case DXGI_FORMAT_R8G8_UINT: out = SurfaceFormat::Rg8UInt; return true;
    case DXGI_FORMAT_R8G8_SINT: out = SurfaceFormat::Rg8SInt; return true;
    case DXGI_FORMAT_R8G8B8A8_UINT: out = SurfaceFormat::Rgba8UInt; return true;
    case DXGI_FORMAT_R8G8B8A8_SINT: out = SurfaceFormat::Rgba8SInt; return true;
    case DXGI_FORMAT_B8G8R8A8_UNORM: out = SurfaceFormat::Bgra32; return true;
    case DXGI_FORMAT_B8G8R8A8_UNORM_SRGB: out = SurfaceFormat::Bgra32SRgb; return true;
    case DXGI_FORMAT_R16_UNORM: out = SurfaceFormat::R16; return true;
    case DXGI_FORMAT_R8G8_UNORM: out = SurfaceFormat::Rg8; return true;
    case DXGI_FORMAT_R8_UNORM: out = SurfaceFormat::R8; return true;
    case DXGI_FORMAT_R8G8B8A8_SNORM: out = SurfaceFormat::NormalizedByte4; return true;
    case DXGI_FORMAT_R8G8_SNORM: out = SurfaceFormat::NormalizedByte2; return true;
    default: return false;
    }
}

bool depthFormat(DXGI_FORMAT f, DepthFormat& out) {
    switch (f) {
    case DXGI_FORMAT_D24_UNORM_S8_UINT: out = DepthFormat::Depth24Stencil8; return true;
    case DXGI_FORMAT_D16_UNORM: out = DepthFormat::Depth16; return true;
    case DXGI_FORMAT_D32_FLOAT: out = DepthFormat::Depth32F; return true;
    default: return false;
    }
}

}  // namespace fxport::d3d11
