// XNA 4 surface and depth formats. Each maps to one GL internal format (see src/gl_formats.cpp);
// the table below is the public view of what a texel holds.
#pragma once

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
};

enum class DepthFormat : std::uint8_t { None, Depth16, Depth24, Depth24Stencil8 };

// What happens to a render target's contents when it is set as a target again, as XNA 4 on Windows:
// SetRenderTarget(s) clears a DiscardContents target (colour to GraphicsDevice::DiscardColor, depth
// to 1, stencil to 0; the back buffer follows PresentationParameters::RenderTargetUsage);
// PreserveContents (and PlatformContents, treated alike) keeps them. See graphics_device.h.
enum class RenderTargetUsage : std::uint8_t { DiscardContents, PreserveContents, PlatformContents };

// Bytes of one texel (what SetData/GetData exchange per pixel).
int bytesPerPixel(SurfaceFormat format);
// "Color", "HalfVector4" ... for messages.
const char* surfaceFormatName(SurfaceFormat format);
const char* depthFormatName(DepthFormat format);

}  // namespace fxport
