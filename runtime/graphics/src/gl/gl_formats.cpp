#include "gl/gl_formats.h"

#include <algorithm>
#include <array>
#include <iterator>

#include "device/surface_formats.h"

namespace fxport {

namespace {

// EXT_texture_sRGB's S3TC formats (not in glcorearb.h; Mesa and NVIDIA have them with S3TC).
constexpr GLenum kSrgbDxt1 = 0x8C4D, kSrgbDxt3 = 0x8C4E, kSrgbDxt5 = 0x8C4F;

// Indexed by SurfaceFormat. Bgr565/Bgra5551/Bgra4444 use GL's packed types with BGRA order so the
// bytes XNA hands us upload unchanged.
const std::array<detail::GlTextureFormat, kSurfaceFormatCount> kFormats = {{
    {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, 4, false, false},                     // Color
    {GL_RGB565, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 2, 3, false, false},              // Bgr565
    {GL_RGB5_A1, GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV, 2, 4, false, false},      // Bgra5551
    {GL_RGBA4, GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV, 2, 4, false, false},        // Bgra4444
    {GL_R8, GL_RED, GL_UNSIGNED_BYTE, 1, 1, false, false},                         // Alpha8 (read as .r; see DESIGN)
    {GL_RGB10_A2, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, 4, 4, false, false},    // Rgba1010102
    {GL_RG16, GL_RG, GL_UNSIGNED_SHORT, 4, 2, false, false},                       // Rg32
    {GL_RGBA16, GL_RGBA, GL_UNSIGNED_SHORT, 8, 4, false, false},                   // Rgba64
    {GL_RG8_SNORM, GL_RG, GL_BYTE, 2, 2, false, false},                            // NormalizedByte2
    {GL_RGBA8_SNORM, GL_RGBA, GL_BYTE, 4, 4, false, false},                        // NormalizedByte4
    {GL_R32F, GL_RED, GL_FLOAT, 4, 1, true, false},                                // Single
    {GL_RG32F, GL_RG, GL_FLOAT, 8, 2, true, false},                                // Vector2
    {GL_RGBA32F, GL_RGBA, GL_FLOAT, 16, 4, true, false},                           // Vector4
    {GL_R16F, GL_RED, GL_HALF_FLOAT, 2, 1, true, false},                           // HalfSingle
    {GL_RG16F, GL_RG, GL_HALF_FLOAT, 4, 2, true, false},                           // HalfVector2
    {GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, 8, 4, true, false},                       // HalfVector4
    {GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, 8, 4, true, false},                       // HdrBlendable
    {GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, 4, 1, true, false},      // Depth32
    {GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, 4, false, false},              // ColorSRgb
    {GL_R32UI, GL_RED_INTEGER, GL_UNSIGNED_INT, 4, 1, false, true},         // R32UInt
    {GL_R32I, GL_RED_INTEGER, GL_INT, 4, 1, false, true},                   // R32SInt
    {GL_RG32UI, GL_RG_INTEGER, GL_UNSIGNED_INT, 8, 2, false, true},         // Rg32UInt
    {GL_RG32I, GL_RG_INTEGER, GL_INT, 8, 2, false, true},                   // Rg32SInt
    {GL_RGBA32UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT, 16, 4, false, true},    // Rgba32UInt
    {GL_RGBA32I, GL_RGBA_INTEGER, GL_INT, 16, 4, false, true},              // Rgba32SInt
    {GL_R16UI, GL_RED_INTEGER, GL_UNSIGNED_SHORT, 2, 1, false, true},       // R16UInt
    {GL_R16I, GL_RED_INTEGER, GL_SHORT, 2, 1, false, true},                 // R16SInt
    {GL_RG16UI, GL_RG_INTEGER, GL_UNSIGNED_SHORT, 4, 2, false, true},       // Rg16UInt
    {GL_RG16I, GL_RG_INTEGER, GL_SHORT, 4, 2, false, true},                 // Rg16SInt
    {GL_RGBA16UI, GL_RGBA_INTEGER, GL_UNSIGNED_SHORT, 8, 4, false, true},   // Rgba16UInt
    {GL_RGBA16I, GL_RGBA_INTEGER, GL_SHORT, 8, 4, false, true},             // Rgba16SInt
    {GL_R8UI, GL_RED_INTEGER, GL_UNSIGNED_BYTE, 1, 1, false, true},         // R8UInt
    {GL_R8I, GL_RED_INTEGER, GL_BYTE, 1, 1, false, true},                   // R8SInt
    {GL_RG8UI, GL_RG_INTEGER, GL_UNSIGNED_BYTE, 2, 2, false, true},         // Rg8UInt
    {GL_RG8I, GL_RG_INTEGER, GL_BYTE, 2, 2, false, true},                   // Rg8SInt
    {GL_RGBA8UI, GL_RGBA_INTEGER, GL_UNSIGNED_BYTE, 4, 4, false, true},     // Rgba8UInt
    {GL_RGBA8I, GL_RGBA_INTEGER, GL_BYTE, 4, 4, false, true},               // Rgba8SInt
    {GL_RGBA8, GL_BGRA, GL_UNSIGNED_BYTE, 4, 4, false, false},              // Bgra32 (bytes B, G, R, A)
    {GL_SRGB8_ALPHA8, GL_BGRA, GL_UNSIGNED_BYTE, 4, 4, false, false},       // Bgra32SRgb
    {GL_R16, GL_RED, GL_UNSIGNED_SHORT, 2, 1, false, false},                // R16
    {GL_RG8, GL_RG, GL_UNSIGNED_BYTE, 2, 2, false, false},                  // Rg8
    {GL_R8, GL_RED, GL_UNSIGNED_BYTE, 1, 1, false, false},                  // R8
    {GL_DEPTH24_STENCIL8, GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, 4, 1, false, false},  // Depth24Stencil8
    {GL_DEPTH_COMPONENT16, GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, 2, 1, false, false},  // Depth16
    // Block-compressed: bytesPerPixel is a 4x4 block's bytes. BC1 is read with its 1-bit alpha, as D3D does.
    {GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, 0, 0, 8, 4, false, false, true},   // Dxt1
    {GL_COMPRESSED_RGBA_S3TC_DXT3_EXT, 0, 0, 16, 4, false, false, true},  // Dxt3
    {GL_COMPRESSED_RGBA_S3TC_DXT5_EXT, 0, 0, 16, 4, false, false, true},  // Dxt5
    {kSrgbDxt1, 0, 0, 8, 4, false, false, true},                          // Dxt1SRgb
    {kSrgbDxt3, 0, 0, 16, 4, false, false, true},                         // Dxt3SRgb
    {kSrgbDxt5, 0, 0, 16, 4, false, false, true},                         // Dxt5SRgb
    {GL_COMPRESSED_RED_RGTC1, 0, 0, 8, 1, false, false, true},            // Bc4
    {GL_COMPRESSED_SIGNED_RED_RGTC1, 0, 0, 8, 1, false, false, true},     // Bc4SNorm
    {GL_COMPRESSED_RG_RGTC2, 0, 0, 16, 2, false, false, true},            // Bc5
    {GL_COMPRESSED_SIGNED_RG_RGTC2, 0, 0, 16, 2, false, false, true},     // Bc5SNorm
    {GL_COMPRESSED_RGB_BPTC_UNSIGNED_FLOAT, 0, 0, 16, 3, true, false, true},  // Bc6hUFloat
    {GL_COMPRESSED_RGB_BPTC_SIGNED_FLOAT, 0, 0, 16, 3, true, false, true},    // Bc6hSFloat
    {GL_COMPRESSED_RGBA_BPTC_UNORM, 0, 0, 16, 4, false, false, true},         // Bc7
    {GL_COMPRESSED_SRGB_ALPHA_BPTC_UNORM, 0, 0, 16, 4, false, false, true},   // Bc7SRgb
    {GL_R11F_G11F_B10F, GL_RGB, GL_UNSIGNED_INT_10F_11F_11F_REV, 4, 3, true, false},  // Rg11B10Float
    {GL_RGB9_E5, GL_RGB, GL_UNSIGNED_INT_5_9_9_9_REV, 4, 3, true, false},             // Rgb9E5Float
    {GL_R16_SNORM, GL_RED, GL_SHORT, 2, 1, false, false},                             // R16SNorm
    {GL_RG16_SNORM, GL_RG, GL_SHORT, 4, 2, false, false},                             // Rg16SNorm
    {GL_RGBA16_SNORM, GL_RGBA, GL_SHORT, 8, 4, false, false},                         // Rgba16SNorm
    {GL_RGB10_A2UI, GL_RGBA_INTEGER, GL_UNSIGNED_INT_2_10_10_10_REV, 4, 4, false, true},  // Rgb10A2UInt
    // No alpha stored: GL drops the fourth byte on upload and reads alpha as 1 (sampling, blending).
    {GL_RGB8, GL_BGRA, GL_UNSIGNED_BYTE, 4, 4, false, false},   // Bgrx32
    {GL_SRGB8, GL_BGRA, GL_UNSIGNED_BYTE, 4, 4, false, false},  // Bgrx32SRgb
    {GL_DEPTH32F_STENCIL8, GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, 8, 1, true, false},  // Depth32Stencil8
    // Views of the depth-stencil texels (the internal format a view must keep), read as stencil
    // indices (GlBackend::createTextureView): integers.
    {GL_DEPTH24_STENCIL8, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, 4, 2, false, true},   // StencilOfDepth24Stencil8
    {GL_DEPTH32F_STENCIL8, GL_STENCIL_INDEX, GL_UNSIGNED_BYTE, 8, 2, false, true},  // StencilOfDepth32Stencil8
}};

const char* const kFormatNames[] = {
    "Color", "Bgr565", "Bgra5551", "Bgra4444", "Alpha8", "Rgba1010102", "Rg32", "Rgba64",
    "NormalizedByte2", "NormalizedByte4", "Single", "Vector2", "Vector4", "HalfSingle",
    "HalfVector2", "HalfVector4", "HdrBlendable", "Depth32", "ColorSRgb",
    "R32UInt", "R32SInt", "Rg32UInt", "Rg32SInt", "Rgba32UInt", "Rgba32SInt",
    "R16UInt", "R16SInt", "Rg16UInt", "Rg16SInt", "Rgba16UInt", "Rgba16SInt",
    "R8UInt", "R8SInt", "Rg8UInt", "Rg8SInt", "Rgba8UInt", "Rgba8SInt",
    "Bgra32", "Bgra32SRgb", "R16", "Rg8", "R8", "Depth24Stencil8", "Depth16",
    "Dxt1", "Dxt3", "Dxt5", "Dxt1SRgb", "Dxt3SRgb", "Dxt5SRgb", "Bc4", "Bc4SNorm", "Bc5", "Bc5SNorm",
    "Bc6hUFloat", "Bc6hSFloat", "Bc7", "Bc7SRgb", "Rg11B10Float", "Rgb9E5Float", "R16SNorm", "Rg16SNorm",
    "Rgba16SNorm", "Rgb10A2UInt", "Bgrx32", "Bgrx32SRgb", "Depth32Stencil8", "StencilOfDepth24Stencil8", "StencilOfDepth32Stencil8",
};
static_assert(std::size(kFormatNames) == kFormats.size(), "one name per SurfaceFormat");
static_assert(std::size_t(SurfaceFormat::StencilOfDepth32Stencil8) + 1 == kFormats.size(), "one row per SurfaceFormat");

}  // namespace

int bytesPerPixel(SurfaceFormat format) { return kFormats.at(std::size_t(format)).bytesPerPixel; }
int channelCount(SurfaceFormat format) { return kFormats.at(std::size_t(format)).channels; }
bool isFloatFormat(SurfaceFormat format) { return kFormats.at(std::size_t(format)).isFloat; }
bool isIntegerFormat(SurfaceFormat format) { return kFormats.at(std::size_t(format)).isInteger; }
bool isCompressedFormat(SurfaceFormat format) { return kFormats.at(std::size_t(format)).isCompressed; }
std::size_t rowBytes(SurfaceFormat format, int width) {
    const int texels = isCompressedFormat(format) ? (width + 3) / 4 : width;
    return std::size_t(std::max(texels, 0)) * std::size_t(bytesPerPixel(format));
}
int rowCount(SurfaceFormat format, int height) { return std::max(isCompressedFormat(format) ? (height + 3) / 4 : height, 0); }
std::size_t regionBytes(SurfaceFormat format, int width, int height) { return rowBytes(format, width) * std::size_t(rowCount(format, height)); }
const char* surfaceFormatName(SurfaceFormat format) { return kFormatNames[std::size_t(format)]; }
const char* depthFormatName(DepthFormat format) {
    switch (format) {
    case DepthFormat::None: return "None";
    case DepthFormat::Depth16: return "Depth16";
    case DepthFormat::Depth24: return "Depth24";
    case DepthFormat::Depth24Stencil8: return "Depth24Stencil8";
    case DepthFormat::Depth32F: return "Depth32F";
    case DepthFormat::Depth32FStencil8: return "Depth32FStencil8";
    }
    return "?";
}

namespace detail {

const GlTextureFormat& glFormat(SurfaceFormat format) { return kFormats.at(std::size_t(format)); }

GLenum glDepthFormat(DepthFormat format) {
    switch (format) {
    case DepthFormat::None: return GL_NONE;
    case DepthFormat::Depth16: return GL_DEPTH_COMPONENT16;
    case DepthFormat::Depth24: return GL_DEPTH_COMPONENT24;
    case DepthFormat::Depth24Stencil8: return GL_DEPTH24_STENCIL8;
    case DepthFormat::Depth32F: return GL_DEPTH_COMPONENT32F;
    case DepthFormat::Depth32FStencil8: return GL_DEPTH32F_STENCIL8;
    }
    return GL_NONE;
}

bool isColorRenderable(SurfaceFormat format) {
    // Snorm formats are not required to be renderable in GL 4.5 core.
    // Nor are shared-exponent texels; compressed ones never are.
    if (isCompressedFormat(format) || format == SurfaceFormat::Rgb9E5Float) return false;
    return format != SurfaceFormat::NormalizedByte2 && format != SurfaceFormat::NormalizedByte4 && format != SurfaceFormat::Depth32 &&
           format != SurfaceFormat::Depth24Stencil8 && format != SurfaceFormat::Depth16 &&
           format != SurfaceFormat::Depth32Stencil8 && format != SurfaceFormat::StencilOfDepth24Stencil8 &&
           format != SurfaceFormat::StencilOfDepth32Stencil8 && format != SurfaceFormat::R16SNorm &&
           format != SurfaceFormat::Rg16SNorm && format != SurfaceFormat::Rgba16SNorm;
}

}  // namespace detail
}  // namespace fxport
