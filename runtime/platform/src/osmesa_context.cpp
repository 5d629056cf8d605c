// OSMesa: a core-profile context rendering on the CPU (llvmpipe) into a buffer we own. fxport renders
// into FBOs; this buffer is only the default framebuffer. llvmpipe's thread count (LP_NUM_THREADS)
// is left to Mesa's defaults.
//
// Texture filtering: llvmpipe's fast path for 8-bit textures ("AoS sampling") rounds every bilinear
// weight to 8 bits, so a shader that offsets its texture coordinates by a sampled value (refraction,
// distortion) drifts by up to ~70/255 from what D3D9-class hardware draws. fxport sets
// GALLIVM_PERF=no_aos_sampling (float weights) before the first context, unless the program or user
// has set GALLIVM_PERF already (docs/testing.md).
#include <GL/osmesa.h>

#include <cstdlib>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "context_base.h"

namespace fxport::platform {
namespace {

void* osmesaProcAddress(const char* name) {
    return reinterpret_cast<void*>(OSMesaGetProcAddress(name));
}

class OSMesaGraphicsContext final : public ContextBase {
public:
    explicit OSMesaGraphicsContext(const ContextDesc& desc)
        : ContextBase(Platform::OSMesa, osmesaProcAddress, desc.width, desc.height),
          pixels_(static_cast<std::size_t>(desc.width) * static_cast<std::size_t>(desc.height)) {
        setenv("GALLIVM_PERF", "no_aos_sampling", 0);  // read by llvmpipe when its first screen is made
        // OSMesa hands out a context of at least the version asked for, or none: ask for 4.5 and
        // step down to 4.1 (below that the GLSL 4.10+ that xlate emits cannot run).
        for (int minor = 5; minor >= 1 && context_ == nullptr; --minor) {
            const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                                   OSMESA_DEPTH_BITS, 24,
                                   OSMESA_STENCIL_BITS, 8,
                                   OSMESA_ACCUM_BITS, 0,
                                   OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                                   OSMESA_CONTEXT_MAJOR_VERSION, 4,
                                   OSMESA_CONTEXT_MINOR_VERSION, minor,
                                   0};
            context_ = OSMesaCreateContextAttribs(attribs, nullptr);
        }
        if (context_ == nullptr) {
            throw std::runtime_error(
                "osmesa: OSMesaCreateContextAttribs gave no OpenGL core context of version 4.1 or "
                "newer (is the Mesa driver llvmpipe? check GALLIUM_DRIVER)");
        }
    }

    ~OSMesaGraphicsContext() override {
        releaseIfCurrent();
        OSMesaDestroyContext(context_);
    }

private:
    void bindNative() override {
        if (!OSMesaMakeCurrent(context_, pixels_.data(), GL_UNSIGNED_BYTE, width(), height())) {
            throw std::runtime_error("osmesa: OSMesaMakeCurrent failed for a " + std::to_string(width()) +
                                     "x" + std::to_string(height()) + " RGBA8 buffer");
        }
    }
    void unbindNative() override { OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0); }

    OSMesaContext context_ = nullptr;
    std::vector<std::uint32_t> pixels_;  // RGBA8, bottom row first; uint32_t keeps it 4-byte aligned
};

}  // namespace

std::unique_ptr<ContextBase> createOSMesaContext(const ContextDesc& desc) {
    return std::make_unique<OSMesaGraphicsContext>(desc);
}

}  // namespace fxport::platform
