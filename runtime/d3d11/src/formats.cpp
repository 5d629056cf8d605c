// DXGI formats -> the device core's texture, depth and vertex formats (those it has).
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
    default: return false;
    }
}

bool depthFormat(DXGI_FORMAT f, DepthFormat& out) {
    switch (f) {
    case DXGI_FORMAT_D24_UNORM_S8_UINT: out = DepthFormat::Depth24Stencil8; return true;
    case DXGI_FORMAT_D16_UNORM: out = DepthFormat::Depth16; return true;
    default: return false;
    }
}

}  // namespace fxport::d3d11
