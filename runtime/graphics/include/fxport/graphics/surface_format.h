// XNA 4 surface and depth formats. Each maps to one GL internal format (see src/gl_formats.cpp);
// the table below is the public view of what a texel holds.
#pragma once

#include <cstddef>
#include <cstdint>

namespace fxport {

enum class SurfaceFormat : std::uint8_t {
    Color,         // RGBA8 unorm (XNA Color's byte order: R, G, B, A)
    Bgr565,
    Bgra5551,
    Bgra4444,
    Alpha8,
    Rgba1010102,
    Rg32,          // RG16 unorm
    Rgba64,        // RGBA16 unorm
    NormalizedByte2,
    NormalizedByte4,
    Single,        // R32F
    Vector2,       // RG32F
    Vector4,       // RGBA32F
    HalfSingle,    // R16F
    HalfVector2,   // RG16F
    HalfVector4,   // RGBA16F
    HdrBlendable,  // RGBA16F (XNA's HDR format on D3D9)
    // fxport additions (XNA has neither):
    Depth32,       // 32-bit float depth texture (SetData/GetData: float), sampled by D3D10
                   // SamplerComparisonState (SampleCmp) for PCF shadows; not a render-target format
    ColorSRgb,     // RGBA8 stored sRGB-encoded: a target D3D9's SRGBWriteEnable encodes into (and
                   // that sampling decodes to linear)
    // Integer texels (D3D10+'s *_UINT / *_SINT formats: Texture2D<uint4>.Load, integer render
    // targets, RWTexture2D<int>). Never filtered: a sampler on them reads the nearest texel of the
    // nearest level. Missing channels read (0, 0, 1) as D3D10 reads them.
    R32UInt, R32SInt, Rg32UInt, Rg32SInt, Rgba32UInt, Rgba32SInt,
    R16UInt, R16SInt, Rg16UInt, Rg16SInt, Rgba16UInt, Rgba16SInt,
    R8UInt, R8SInt, Rg8UInt, Rg8SInt, Rgba8UInt, Rgba8SInt,
    Bgra32,      // BGRA8 unorm in memory (D3D's B8G8R8A8_UNORM): shaders read (r, g, b, a)
    Bgra32SRgb,  // the same, sRGB-encoded
    R16,         // R16 unorm
    Rg8,         // RG8 unorm
    R8,          // R8 unorm (read as (r, 0, 0, 1), not XNA Alpha8's (0, 0, 0, a))
    // Depth textures a shader samples (D3D's R24G8_TYPELESS / R16_TYPELESS shadow maps, read as
    // R24_UNORM_X8_TYPELESS / R16_UNORM): (depth, 0, 0, 1), or compared by SampleCmp. Like Depth32,
    // not colour render targets.
    Depth24Stencil8,  // 24-bit unorm depth and 8-bit stencil (SetData/GetData: one uint32, depth in the high 24 bits)
    Depth16,          // 16-bit unorm depth (SetData/GetData: uint16)
    // Block-compressed texels, stored and sampled compressed (XNA's Dxt1/Dxt3/Dxt5 are D3D's
    // BC1/BC2/BC3). They hold 4x4-texel blocks of 8 bytes (Dxt1, Bc4) or 16: SetData/GetData exchange
    // whole blocks, rows of blocks top first, and a rectangle's corners lie on the 4-texel grid or the
    // level's edge, as in D3D. Sampled only: never render targets or storage.
    Dxt1, Dxt3, Dxt5,
    Dxt1SRgb, Dxt3SRgb, Dxt5SRgb,  // the same, sRGB-encoded (D3D's BC1-3 _UNORM_SRGB)
    Bc4, Bc4SNorm,                 // one channel (r, 0, 0, 1)
    Bc5, Bc5SNorm,                 // two channels (r, g, 0, 1): normal maps
    Bc6hUFloat, Bc6hSFloat,        // HDR (r, g, b, 1) halves
    Bc7, Bc7SRgb,
    // More of D3D10+'s uncompressed formats:
    Rg11B10Float,  // packed unsigned floats, 11-11-10 bits (D3D's R11G11B10_FLOAT, an HDR target)
    Rgb9E5Float,   // a shared 5-bit exponent (D3D's R9G9B9E5_SHAREDEXP): sampled only
    R16SNorm, Rg16SNorm, Rgba16SNorm,
    Rgb10A2UInt,   // D3D's R10G10B10A2_UINT
    Bgrx32,        // BGRX8 unorm in memory (D3D's B8G8R8X8_UNORM): the fourth byte is unused, alpha reads 1
    Bgrx32SRgb,    // the same, sRGB-encoded
    Depth32Stencil8,  // 32-bit float depth and 8-bit stencil in 8 bytes (D3D's R32G8X24_TYPELESS shadow map)
    // The stencil of a Depth24Stencil8 / Depth32Stencil8 texture, read as an unsigned integer in
    // green, (0, stencil, 0, 1): D3D's X24_TYPELESS_G8_UINT / X32_TYPELESS_G8X24_UINT views
    // (Texture2D<uint2>.Load(p).g). Only a view of such a texture has it (Texture2D's view
    // constructor); never filtered, never a target.
    StencilOfDepth24Stencil8, StencilOfDepth32Stencil8,
};

enum class DepthFormat : std::uint8_t {
    None, Depth16, Depth24, Depth24Stencil8,
    Depth32F,  // fxport addition (D3D10+'s D32_FLOAT): 32-bit float depth, no stencil
    Depth32FStencil8,  // fxport addition (D3D10+'s D32_FLOAT_S8X24_UINT): 32-bit float depth and 8-bit stencil
};
inline constexpr int kSurfaceFormatCount = int(SurfaceFormat::StencilOfDepth32Stencil8) + 1;

inline bool hasStencil(DepthFormat f) { return f == DepthFormat::Depth24Stencil8 || f == DepthFormat::Depth32FStencil8; }

// What happens to a render target's contents when it is set as a target again, as XNA 4 on Windows:
// SetRenderTarget(s) clears a DiscardContents target (colour to GraphicsDevice::DiscardColor, depth
// to 1, stencil to 0; the back buffer follows PresentationParameters::RenderTargetUsage);
// PreserveContents (and PlatformContents, treated alike) keeps them. See graphics_device.h.
enum class RenderTargetUsage : std::uint8_t { DiscardContents, PreserveContents, PlatformContents };

// Bytes of one texel (what SetData/GetData exchange per pixel); of one 4x4 block for the
// block-compressed formats.
int bytesPerPixel(SurfaceFormat format);
// Whether texels come in 4x4 blocks (Dxt1 ... Bc7SRgb).
bool isCompressedFormat(SurfaceFormat format);
// The layout SetData/GetData and D3D's pitches use, for any format (a plain format's "block" is one
// texel): the bytes of one row of blocks `width` texels wide, the rows of blocks `height` texels
// high, and the bytes of a width x height region (rowBytes * rowCount).
std::size_t rowBytes(SurfaceFormat format, int width);
int rowCount(SurfaceFormat format, int height);
std::size_t regionBytes(SurfaceFormat format, int width, int height);
// Whether texels are integers (R32UInt ... Rgba8SInt): sampled unfiltered, cleared with integers.
bool isIntegerFormat(SurfaceFormat format);
// "Color", "HalfVector4" ... for messages.
const char* surfaceFormatName(SurfaceFormat format);
const char* depthFormatName(DepthFormat format);

}  // namespace fxport
