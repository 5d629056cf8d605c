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
    case DXGI_FORMAT_R32G8X24_TYPELESS: return "DXGI_FORMAT_R32G8X24_TYPELESS";
    case DXGI_FORMAT_D32_FLOAT_S8X24_UINT: return "DXGI_FORMAT_D32_FLOAT_S8X24_UINT";
    case DXGI_FORMAT_R32_FLOAT_X8X24_TYPELESS: return "DXGI_FORMAT_R32_FLOAT_X8X24_TYPELESS";
    case DXGI_FORMAT_X32_TYPELESS_G8X24_UINT: return "DXGI_FORMAT_X32_TYPELESS_G8X24_UINT";
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
    case DXGI_FORMAT_B8G8R8X8_UNORM: return "DXGI_FORMAT_B8G8R8X8_UNORM";
    case DXGI_FORMAT_B8G8R8X8_TYPELESS: return "DXGI_FORMAT_B8G8R8X8_TYPELESS";
    case DXGI_FORMAT_B8G8R8X8_UNORM_SRGB: return "DXGI_FORMAT_B8G8R8X8_UNORM_SRGB";
    case DXGI_FORMAT_B8G8R8A8_UNORM_SRGB: return "DXGI_FORMAT_B8G8R8A8_UNORM_SRGB";
    case DXGI_FORMAT_R9G9B9E5_SHAREDEXP: return "DXGI_FORMAT_R9G9B9E5_SHAREDEXP";
    case DXGI_FORMAT_BC1_TYPELESS: return "DXGI_FORMAT_BC1_TYPELESS";
    case DXGI_FORMAT_BC1_UNORM: return "DXGI_FORMAT_BC1_UNORM";
    case DXGI_FORMAT_BC1_UNORM_SRGB: return "DXGI_FORMAT_BC1_UNORM_SRGB";
    case DXGI_FORMAT_BC2_TYPELESS: return "DXGI_FORMAT_BC2_TYPELESS";
    case DXGI_FORMAT_BC2_UNORM: return "DXGI_FORMAT_BC2_UNORM";
    case DXGI_FORMAT_BC2_UNORM_SRGB: return "DXGI_FORMAT_BC2_UNORM_SRGB";
    case DXGI_FORMAT_BC3_TYPELESS: return "DXGI_FORMAT_BC3_TYPELESS";
    case DXGI_FORMAT_BC3_UNORM: return "DXGI_FORMAT_BC3_UNORM";
    case DXGI_FORMAT_BC3_UNORM_SRGB: return "DXGI_FORMAT_BC3_UNORM_SRGB";
    case DXGI_FORMAT_BC4_TYPELESS: return "DXGI_FORMAT_BC4_TYPELESS";
    case DXGI_FORMAT_BC4_UNORM: return "DXGI_FORMAT_BC4_UNORM";
    case DXGI_FORMAT_BC4_SNORM: return "DXGI_FORMAT_BC4_SNORM";
    case DXGI_FORMAT_BC5_TYPELESS: return "DXGI_FORMAT_BC5_TYPELESS";
    case DXGI_FORMAT_BC5_UNORM: return "DXGI_FORMAT_BC5_UNORM";
    case DXGI_FORMAT_BC5_SNORM: return "DXGI_FORMAT_BC5_SNORM";
    case DXGI_FORMAT_B5G6R5_UNORM: return "DXGI_FORMAT_B5G6R5_UNORM";
    case DXGI_FORMAT_B5G5R5A1_UNORM: return "DXGI_FORMAT_B5G5R5A1_UNORM";
    case DXGI_FORMAT_BC6H_TYPELESS: return "DXGI_FORMAT_BC6H_TYPELESS";
    case DXGI_FORMAT_BC6H_UF16: return "DXGI_FORMAT_BC6H_UF16";
    case DXGI_FORMAT_BC6H_SF16: return "DXGI_FORMAT_BC6H_SF16";
    case DXGI_FORMAT_BC7_TYPELESS: return "DXGI_FORMAT_BC7_TYPELESS";
    case DXGI_FORMAT_BC7_UNORM: return "DXGI_FORMAT_BC7_UNORM";
    case DXGI_FORMAT_BC7_UNORM_SRGB: return "DXGI_FORMAT_BC7_UNORM_SRGB";
    case DXGI_FORMAT_B4G4R4A4_UNORM: return "DXGI_FORMAT_B4G4R4A4_UNORM";
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
    case DXGI_FORMAT_B8G8R8X8_UNORM: out = SurfaceFormat::Bgrx32; return true;  // X: alpha reads 1
    case DXGI_FORMAT_B8G8R8X8_UNORM_SRGB: out = SurfaceFormat::Bgrx32SRgb; return true;
    case DXGI_FORMAT_R16_UNORM: out = SurfaceFormat::R16; return true;
    case DXGI_FORMAT_R8G8_UNORM: out = SurfaceFormat::Rg8; return true;
    case DXGI_FORMAT_R8_UNORM: out = SurfaceFormat::R8; return true;
    case DXGI_FORMAT_R8G8B8A8_SNORM: out = SurfaceFormat::NormalizedByte4; return true;
    case DXGI_FORMAT_R8G8_SNORM: out = SurfaceFormat::NormalizedByte2; return true;
    case DXGI_FORMAT_R16_SNORM: out = SurfaceFormat::R16SNorm; return true;
    case DXGI_FORMAT_R16G16_SNORM: out = SurfaceFormat::Rg16SNorm; return true;
    case DXGI_FORMAT_R16G16B16A16_SNORM: out = SurfaceFormat::Rgba16SNorm; return true;
    case DXGI_FORMAT_R10G10B10A2_UINT: out = SurfaceFormat::Rgb10A2UInt; return true;
    case DXGI_FORMAT_R11G11B10_FLOAT: out = SurfaceFormat::Rg11B10Float; return true;
    case DXGI_FORMAT_R9G9B9E5_SHAREDEXP: out = SurfaceFormat::Rgb9E5Float; return true;
    // XNA's 16-bit formats are D3D's B5G6R5/B5G5R5A1/B4G4R4A4 bit for bit.
    case DXGI_FORMAT_B5G6R5_UNORM: out = SurfaceFormat::Bgr565; return true;
    case DXGI_FORMAT_B5G5R5A1_UNORM: out = SurfaceFormat::Bgra5551; return true;
    case DXGI_FORMAT_B4G4R4A4_UNORM: out = SurfaceFormat::Bgra4444; return true;
    // Block-compressed (a _TYPELESS one is a texture of its family, typeless_formats.cpp)
    case DXGI_FORMAT_BC1_UNORM: out = SurfaceFormat::Dxt1; return true;
    case DXGI_FORMAT_BC2_UNORM: out = SurfaceFormat::Dxt3; return true;
    case DXGI_FORMAT_BC3_UNORM: out = SurfaceFormat::Dxt5; return true;
    case DXGI_FORMAT_BC1_UNORM_SRGB: out = SurfaceFormat::Dxt1SRgb; return true;
    case DXGI_FORMAT_BC2_UNORM_SRGB: out = SurfaceFormat::Dxt3SRgb; return true;
    case DXGI_FORMAT_BC3_UNORM_SRGB: out = SurfaceFormat::Dxt5SRgb; return true;
    case DXGI_FORMAT_BC4_UNORM: out = SurfaceFormat::Bc4; return true;
    case DXGI_FORMAT_BC4_SNORM: out = SurfaceFormat::Bc4SNorm; return true;
    case DXGI_FORMAT_BC5_UNORM: out = SurfaceFormat::Bc5; return true;
    case DXGI_FORMAT_BC5_SNORM: out = SurfaceFormat::Bc5SNorm; return true;
    case DXGI_FORMAT_BC6H_UF16: out = SurfaceFormat::Bc6hUFloat; return true;
    case DXGI_FORMAT_BC6H_SF16: out = SurfaceFormat::Bc6hSFloat; return true;
    case DXGI_FORMAT_BC7_UNORM: out = SurfaceFormat::Bc7; return true;
    case DXGI_FORMAT_BC7_UNORM_SRGB: out = SurfaceFormat::Bc7SRgb; return true;
    default: return false;
    }
}

HRESULT checkCompressedUse(const std::string& at, const D3D11_TEXTURE2D_DESC& d, SurfaceFormat format) {
    if (!isCompressedFormat(format)) return S_OK;
    const UINT drawn = D3D11_BIND_RENDER_TARGET | D3D11_BIND_DEPTH_STENCIL | D3D11_BIND_UNORDERED_ACCESS;
    const std::string with = " with Format = " + std::string(formatName(d.Format)) + ": block-compressed textures are only sampled";
    if (d.BindFlags & drawn) return fail(E_INVALIDARG, at + "BindFlags = " + std::to_string(d.BindFlags) + with);
    if (d.SampleDesc.Count > 1) return fail(E_INVALIDARG, at + "SampleDesc.Count = " + std::to_string(d.SampleDesc.Count) + with);
    if (d.MiscFlags & D3D11_RESOURCE_MISC_GENERATE_MIPS) return fail(E_INVALIDARG, at + "MiscFlags = D3D11_RESOURCE_MISC_GENERATE_MIPS" + with);
    return S_OK;
}

bool depthFormat(DXGI_FORMAT f, DepthFormat& out) {
    switch (f) {
    case DXGI_FORMAT_D24_UNORM_S8_UINT: out = DepthFormat::Depth24Stencil8; return true;
    case DXGI_FORMAT_D16_UNORM: out = DepthFormat::Depth16; return true;
    case DXGI_FORMAT_D32_FLOAT: out = DepthFormat::Depth32F; return true;
    case DXGI_FORMAT_D32_FLOAT_S8X24_UINT: out = DepthFormat::Depth32FStencil8; return true;
    default: return false;
    }
}

}  // namespace fxport::d3d11
