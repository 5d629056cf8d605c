// EGL device platform: a headless GPU context with no X server or Wayland (EGL_EXT_platform_device).
// Written for NVIDIA's proprietary driver behind libglvnd as well as Mesa; the path follows NVIDIA's
// own headless recipe: eglQueryDevicesEXT -> eglGetPlatformDisplayEXT(EGL_PLATFORM_DEVICE_EXT) ->
// eglInitialize -> eglChooseConfig(PBUFFER) -> eglBindAPI(OPENGL) -> eglCreateContext(4.5 core).
#include <EGL/egl.h>
#include <EGL/eglext.h>

#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "context_base.h"

namespace fxport::platform {
namespace {

void* eglProcAddress(const char* name) { return reinterpret_cast<void*>(eglGetProcAddress(name)); }

std::string eglErrorText(EGLint error) {
    const char* name = nullptr;
    switch (error) {
        case EGL_SUCCESS: name = "EGL_SUCCESS"; break;
        case EGL_NOT_INITIALIZED: name = "EGL_NOT_INITIALIZED"; break;
        case EGL_BAD_ACCESS: name = "EGL_BAD_ACCESS"; break;
        case EGL_BAD_ALLOC: name = "EGL_BAD_ALLOC"; break;
        case EGL_BAD_ATTRIBUTE: name = "EGL_BAD_ATTRIBUTE"; break;
        case EGL_BAD_CONFIG: name = "EGL_BAD_CONFIG"; break;
        case EGL_BAD_CONTEXT: name = "EGL_BAD_CONTEXT"; break;
        case EGL_BAD_CURRENT_SURFACE: name = "EGL_BAD_CURRENT_SURFACE"; break;
        case EGL_BAD_DISPLAY: name = "EGL_BAD_DISPLAY"; break;
        case EGL_BAD_MATCH: name = "EGL_BAD_MATCH"; break;
        case EGL_BAD_NATIVE_PIXMAP: name = "EGL_BAD_NATIVE_PIXMAP"; break;
        case EGL_BAD_NATIVE_WINDOW: name = "EGL_BAD_NATIVE_WINDOW"; break;
        case EGL_BAD_PARAMETER: name = "EGL_BAD_PARAMETER"; break;
        case EGL_BAD_SURFACE: name = "EGL_BAD_SURFACE"; break;
        case EGL_CONTEXT_LOST: name = "EGL_CONTEXT_LOST"; break;
        default: break;
    }
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%04X", static_cast<unsigned>(error));
    return name != nullptr ? std::string(name) + " (" + hex + ")" : std::string("EGL error ") + hex;
}

// The error of the last EGL call, as text; `what` names the call.
std::string lastEglError(const char* what) { return std::string(what) + " failed: " + eglErrorText(eglGetError()); }

bool hasExtension(const char* list, const char* name) {
    if (list == nullptr) return false;
    const std::string all = std::string(" ") + list + " ";
    return all.find(std::string(" ") + name + " ") != std::string::npos;
}

// Device displays are one per device and process; eglTerminate would destroy every context on it.
// Count our users and terminate with the last one.
std::map<EGLDisplay, int>& displayUsers() {
    static std::map<EGLDisplay, int> users;
    return users;
}

void releaseDisplay(EGLDisplay display) {
    auto& users = displayUsers();
    auto it = users.find(display);
    if (it != users.end() && --it->second == 0) {
        users.erase(it);
        eglTerminate(display);
    }
}

class EGLGraphicsContext final : public ContextBase {
public:
    explicit EGLGraphicsContext(const ContextDesc& desc)
        : ContextBase(Platform::EGL, eglProcAddress, desc.width, desc.height) {
        const char* clientExtensions = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
        if (!hasExtension(clientExtensions, "EGL_EXT_platform_device") ||
            !(hasExtension(clientExtensions, "EGL_EXT_device_enumeration") ||
              hasExtension(clientExtensions, "EGL_EXT_device_base"))) {
            throw std::runtime_error(
                "egl: this EGL lacks EGL_EXT_platform_device/EGL_EXT_device_enumeration (client "
                "extensions: " + std::string(clientExtensions ? clientExtensions : "none") + ")");
        }
        auto queryDevices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        auto queryDeviceString =
            reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
        auto getPlatformDisplay =
            reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (queryDevices == nullptr || getPlatformDisplay == nullptr) {
            throw std::runtime_error("egl: eglQueryDevicesEXT/eglGetPlatformDisplayEXT not found");
        }

        EGLint count = 0;
        if (!queryDevices(0, nullptr, &count)) throw std::runtime_error("egl: " + lastEglError("eglQueryDevicesEXT"));
        std::vector<EGLDeviceEXT> devices(static_cast<std::size_t>(count));
        if (count > 0 && !queryDevices(count, devices.data(), &count)) {
            throw std::runtime_error("egl: " + lastEglError("eglQueryDevicesEXT"));
        }
        devices.resize(static_cast<std::size_t>(count));

        // GPUs first: Mesa adds a software device (EGL_MESA_device_software) that would also work,
        // but on a GPU machine the GPU is what EGL is asked for. Software stays as the last resort.
        std::vector<EGLDeviceEXT> ordered;
        for (int pass = 0; pass < 2; ++pass) {
            for (EGLDeviceEXT device : devices) {
                const char* ext = queryDeviceString ? queryDeviceString(device, EGL_EXTENSIONS) : nullptr;
                if (hasExtension(ext, "EGL_MESA_device_software") == (pass == 1)) ordered.push_back(device);
            }
        }

        std::string failures;
        for (std::size_t i = 0; i < ordered.size(); ++i) {
            std::string why = tryDevice(getPlatformDisplay, ordered[i], desc);
            if (why.empty()) return;
            failures += "\n  device " + std::to_string(i) + ": " + why;
        }
        throw std::runtime_error("egl: no EGL device gave an OpenGL 4.5 core context (" +
                                 std::to_string(ordered.size()) + " device(s) found)" + failures);
    }

    ~EGLGraphicsContext() override {
        releaseIfCurrent();
        destroy();
    }

private:
    // Builds everything on one device; returns "" on success, else why not (and leaves nothing behind).
    std::string tryDevice(PFNEGLGETPLATFORMDISPLAYEXTPROC getPlatformDisplay, EGLDeviceEXT device,
                          const ContextDesc& desc) {
        display_ = getPlatformDisplay(EGL_PLATFORM_DEVICE_EXT, device, nullptr);
        if (display_ == EGL_NO_DISPLAY) return lastEglError("eglGetPlatformDisplayEXT");
        EGLint major = 0, minor = 0;
        if (!eglInitialize(display_, &major, &minor)) {
            std::string why = lastEglError("eglInitialize");
            display_ = EGL_NO_DISPLAY;
            return why;
        }
        ++displayUsers()[display_];
        std::string why = createOnDisplay(desc, major, minor);
        if (!why.empty()) destroy();
        return why;
    }

    std::string createOnDisplay(const ContextDesc& desc, EGLint major, EGLint minor) {
        const char* extensions = eglQueryString(display_, EGL_EXTENSIONS);
        const char* vendor = eglQueryString(display_, EGL_VENDOR);
        const std::string where = std::string(vendor ? vendor : "?") + " EGL " + std::to_string(major) + "." +
                                  std::to_string(minor) + ": ";
        // EGL 1.5 has the context attributes in core; before that EGL_KHR_create_context gives them.
        if (major * 10 + minor < 15 && !hasExtension(extensions, "EGL_KHR_create_context")) {
            return where + "no EGL_KHR_create_context (needed for a 4.5 core profile)";
        }
        // Rendering API is per thread; bound before choosing a GL config and creating the context.
        if (!eglBindAPI(EGL_OPENGL_API)) return where + lastEglError("eglBindAPI(EGL_OPENGL_API)");

        const EGLint configAttribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT,
                                        EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT,
                                        EGL_RED_SIZE, 8, EGL_GREEN_SIZE, 8, EGL_BLUE_SIZE, 8, EGL_ALPHA_SIZE, 8,
                                        EGL_DEPTH_SIZE, 24, EGL_STENCIL_SIZE, 8,
                                        EGL_NONE};
        EGLConfig config = nullptr;
        EGLint configCount = 0;
        if (!eglChooseConfig(display_, configAttribs, &config, 1, &configCount)) {
            return where + lastEglError("eglChooseConfig");
        }
        if (configCount == 0) return where + "no RGBA8/D24S8 pbuffer config for desktop OpenGL";

        const EGLint contextAttribs[] = {
            EGL_CONTEXT_MAJOR_VERSION_KHR, 4,
            EGL_CONTEXT_MINOR_VERSION_KHR, 5,
            EGL_CONTEXT_OPENGL_PROFILE_MASK_KHR, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT_KHR,
            EGL_CONTEXT_FLAGS_KHR, desc.debug ? EGL_CONTEXT_OPENGL_DEBUG_BIT_KHR : 0,
            EGL_NONE};
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, contextAttribs);
        if (context_ == EGL_NO_CONTEXT) return where + lastEglError("eglCreateContext(OpenGL 4.5 core)");

        // A pbuffer of the asked size gives a default framebuffer like OSMesa's. Surfaceless is the
        // fallback: fxport renders into FBOs anyway.
        const EGLint pbufferAttribs[] = {EGL_WIDTH, desc.width, EGL_HEIGHT, desc.height, EGL_NONE};
        surface_ = eglCreatePbufferSurface(display_, config, pbufferAttribs);
        if (surface_ == EGL_NO_SURFACE) {
            std::string why = lastEglError("eglCreatePbufferSurface");
            if (!hasExtension(extensions, "EGL_KHR_surfaceless_context")) {
                return where + why + ", and no EGL_KHR_surfaceless_context";
            }
        }
        // Not made current here: GraphicsContext::create() does that through makeCurrent(), which
        // first releases whatever context (of any platform) is current.
        return "";
    }

    void destroy() {
        if (display_ == EGL_NO_DISPLAY) return;
        if (surface_ != EGL_NO_SURFACE) eglDestroySurface(display_, surface_);
        if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
        releaseDisplay(display_);
        surface_ = EGL_NO_SURFACE;
        context_ = EGL_NO_CONTEXT;
        display_ = EGL_NO_DISPLAY;
    }

    void bindNative() override {
        eglBindAPI(EGL_OPENGL_API);  // per thread; cheap
        if (!eglMakeCurrent(display_, surface_, surface_, context_)) {
            throw std::runtime_error("egl: " + lastEglError("eglMakeCurrent"));
        }
    }
    void unbindNative() override { eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT); }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
    EGLSurface surface_ = EGL_NO_SURFACE;  // stays EGL_NO_SURFACE when surfaceless
};

}  // namespace

std::unique_ptr<ContextBase> createEGLContext(const ContextDesc& desc) {
    return std::make_unique<EGLGraphicsContext>(desc);
}

}  // namespace fxport::platform
