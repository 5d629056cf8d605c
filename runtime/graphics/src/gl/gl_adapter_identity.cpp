// The GL half of GraphicsDevice::adapterIdentity(): GL_RENDERER and GL_VENDOR, and the video memory
// from the one of the two vendor extensions that report it (core GL has no query for it).
#include <string_view>

#include "gl/gl_backend.h"

namespace fxport {

namespace {

// glext.h's values (glcorearb.h leaves vendor extensions out).
constexpr GLenum kDedicatedVideoMemoryNvx = 0x9047;  // GL_GPU_MEMORY_INFO_DEDICATED_VIDMEM_NVX, in KiB
constexpr GLenum kTextureFreeMemoryAti = 0x87FC;     // GL_TEXTURE_FREE_MEMORY_ATI: 4 values, [0] the free KiB

std::string glText(GLenum name) {
    const auto* text = reinterpret_cast<const char*>(glGetString(name));
    return text ? text : "";
}

bool hasExtension(std::string_view wanted) {
    GLint count = 0;
    glGetIntegerv(GL_NUM_EXTENSIONS, &count);
    for (GLint i = 0; i < count; ++i) {
        const auto* name = reinterpret_cast<const char*>(glGetStringi(GL_EXTENSIONS, GLuint(i)));
        if (name && wanted == name) return true;
    }
    return false;
}

}  // namespace

AdapterIdentity GlBackend::adapterIdentity() {
    AdapterIdentity id;
    id.renderer = glText(GL_RENDERER);
    id.vendor = glText(GL_VENDOR);
    GLint kib[4] = {};
    if (hasExtension("GL_NVX_gpu_memory_info")) {
        glGetIntegerv(kDedicatedVideoMemoryNvx, kib);
        id.memory = AdapterIdentity::Memory::Dedicated;
    } else if (hasExtension("GL_ATI_meminfo")) {
        glGetIntegerv(kTextureFreeMemoryAti, kib);
        id.memory = AdapterIdentity::Memory::FreeForTextures;
    }
    id.videoMemoryBytes = std::uint64_t(kib[0] > 0 ? kib[0] : 0) * 1024;
    return id;
}

}  // namespace fxport
