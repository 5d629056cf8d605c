// INTERNAL: SurfaceFormat / DepthFormat -> GL formats.
#pragma once

#include "fxport/graphics/surface_format.h"
#include "fxport/platform/gl.h"

namespace fxport::detail {

struct GlTextureFormat {
    GLenum internalFormat;  // for glTextureStorage
    GLenum format;          // client data layout of SetData/GetData
    GLenum type;
    int bytesPerPixel;
    int channels;           // 1..4 (for PNG export)
    bool isFloat;           // float or half texels (PNG export clamps)
    bool isInteger;         // *_INTEGER client formats; sampled unfiltered
    bool isCompressed = false;  // 4x4 blocks of bytesPerPixel bytes (format and type unused)
};

const GlTextureFormat& glFormat(SurfaceFormat format);
GLenum glDepthFormat(DepthFormat format);  // GL_NONE for DepthFormat::None
// Whether the driver can render into this format (all of XNA's render-target formats are
// colour-renderable in GL 4.5 core except the packed 16-bit ones, which we store as RGBA8-class).
bool isColorRenderable(SurfaceFormat format);

}  // namespace fxport::detail
