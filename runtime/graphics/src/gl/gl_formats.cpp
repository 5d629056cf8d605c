#include "gl/gl_formats.h"

#include <array>

#include "device/surface_formats.h"

namespace fxport {

namespace {

// Indexed by SurfaceFormat. Bgr565/Bgra5551/Bgra4444 use GL's packed types with BGRA order so the
// bytes XNA hands us upload unchanged.
const std::array<detail::GlTextureFormat, 19> kFormats = {{
    {GL_RGBA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, 4, false},                     // Color
    {GL_RGB565, GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 2, 3, false},              // Bgr565
    {GL_RGB5_A1, GL_BGRA, GL_UNSIGNED_SHORT_1_5_5_5_REV, 2, 4, false},      // Bgra5551
    {GL_RGBA4, GL_BGRA, GL_UNSIGNED_SHORT_4_4_4_4_REV, 2, 4, false},        // Bgra4444
    {GL_R8, GL_RED, GL_UNSIGNED_BYTE, 1, 1, false},                         // Alpha8 (read as .r; see DESIGN)
    {GL_RGB10_A2, GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, 4, 4, false},    // Rgba1010102
    {GL_RG16, GL_RG, GL_UNSIGNED_SHORT, 4, 2, false},                       // Rg32
    {GL_RGBA16, GL_RGBA, GL_UNSIGNED_SHORT, 8, 4, false},                   // Rgba64
    {GL_RG8_SNORM, GL_RG, GL_BYTE, 2, 2, false},                            // NormalizedByte2
    {GL_RGBA8_SNORM, GL_RGBA, GL_BYTE, 4, 4, false},                        // NormalizedByte4
    {GL_R32F, GL_RED, GL_FLOAT, 4, 1, true},                                // Single
    {GL_RG32F, GL_RG, GL_FLOAT, 8, 2, true},                                // Vector2
    {GL_RGBA32F, GL_RGBA, GL_FLOAT, 16, 4, true},                           // Vector4
    {GL_R16F, GL_RED, GL_HALF_FLOAT, 2, 1, true},                           // HalfSingle
    {GL_RG16F, GL_RG, GL_HALF_FLOAT, 4, 2, true},                           // HalfVector2
    {GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, 8, 4, true},                       // HalfVector4
    {GL_RGBA16F, GL_RGBA, GL_HALF_FLOAT, 8, 4, true},                       // HdrBlendable
    {GL_DEPTH_COMPONENT32F, GL_DEPTH_COMPONENT, GL_FLOAT, 4, 1, true},      // Depth32
    {GL_SRGB8_ALPHA8, GL_RGBA, GL_UNSIGNED_BYTE, 4, 4, false},              // ColorSRgb
}};

const char* const kFormatNames[] = {
    "Color", "Bgr565", "Bgra5551", "Bgra4444", "Alpha8", "Rgba1010102", "Rg32", "Rgba64",
    "NormalizedByte2", "NormalizedByte4", "Single", "Vector2", "Vector4", "HalfSingle",
    "HalfVector2", "HalfVector4", "HdrBlendable", "Depth32", "ColorSRgb",
};

}  // namespace

int bytesPerPixel(SurfaceFormat format) { return kFormats.at(std::size_t(format)).bytesPerPixel; }
int channelCount(SurfaceFormat format) { return kFormats.at(std::size_t(format)).channels; }
bool isFloatFormat(SurfaceFormat format) { return kFormats.at(std::size_t(format)).isFloat; }
const char* surfaceFormatName(SurfaceFormat format) { return kFormatNames[std::size_t(format)]; }
const char* depthFormatName(DepthFormat format) {
    switch (format) {
    case DepthFormat::None: return "None";
    case DepthFormat::Depth16: return "Depth16";
    case DepthFormat::Depth24: return "Depth24";
    case DepthFormat::Depth24Stencil8: return "Depth24Stencil8";
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
    }
    return GL_NONE;
}

bool isColorRenderable(SurfaceFormat format) {
    // Snorm formats are not required to be renderable in GL 4.5 core.
    return format != SurfaceFormat::NormalizedByte2 && format != SurfaceFormat::NormalizedByte4 && format != SurfaceFormat::Depth32;
}

}  // namespace detail
}  // namespace fxport
