#include "fxport/platform/graphics_context.h"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "context_base.h"
#include "fxport/platform/gl.h"

namespace fxport::platform {
namespace {

// GL function pointers are process-wide, so the bookkeeping is too: which context is current and
// which platform's loader filled the pointers. (Single GL thread; see GraphicsContext.)
ContextBase* g_current = nullptr;
ContextBase::ProcLoader g_loadedWith = nullptr;

std::string joinedNames(const std::vector<Platform>& platforms) {
    std::string names;
    for (Platform p : platforms) {
        if (!names.empty()) names += ", ";
        names += platformName(p);
    }
    return names;
}

void APIENTRY printDebugMessage(GLenum, GLenum type, GLuint id, GLenum severity, GLsizei,
                                const GLchar* message, const void*) {
    const char* level = severity == GL_DEBUG_SEVERITY_HIGH     ? "high"
                        : severity == GL_DEBUG_SEVERITY_MEDIUM ? "medium"
                                                               : "low";
    std::fprintf(stderr, "fxport GL debug [%s%s, id %u]: %s\n", level,
                 type == GL_DEBUG_TYPE_ERROR ? ", error" : "", id, message);
}

std::string glString(GLenum name) {
    const GLubyte* s = glGetString(name);
    return s != nullptr ? reinterpret_cast<const char*>(s) : "?";
}

}  // namespace

ContextBase::ContextBase(Platform platform, ProcLoader loader, int width, int height)
    : platform_(platform), loader_(loader), width_(width), height_(height) {}

void ContextBase::makeCurrent() {
    // Release the previous context explicitly. Platforms do not know of each other: OSMesa and Mesa's
    // EGL share one GL dispatch, and an EGL that still believes its context is current may skip
    // rebinding it after OSMesa took the dispatch over.
    if (g_current != nullptr && g_current != this) {
        g_current->unbindNative();
        g_current = nullptr;
    }
    bindNative();
    g_current = this;
    // Pointers from another platform's loader may dispatch elsewhere (glvnd's stubs follow EGL/GLX,
    // OSMesa's follow Mesa's own current context), so reload when the platform changes.
    if (g_loadedWith != loader_) {
        g_loadedWith = nullptr;
        std::string missing;
        if (!gl::loadGLFunctions(loader_, &missing)) {
            throw std::runtime_error(std::string(platformName(platform_)) +
                                     ": the GL driver lacks required functions: " + missing);
        }
        g_loadedWith = loader_;
    }
}

void ContextBase::releaseIfCurrent() {
    if (g_current == this) {
        unbindNative();
        g_current = nullptr;
    }
}

void ContextBase::initialiseGL(bool debug) {
    makeCurrent();
    GLint major = 0, minor = 0, profile = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    rendererName_ = glString(GL_RENDERER) + " / " + glString(GL_VERSION);
    if (major * 10 + minor < 41 || (profile & GL_CONTEXT_CORE_PROFILE_BIT) == 0) {
        throw std::runtime_error(std::string(platformName(platform_)) + ": got OpenGL " +
                                 std::to_string(major) + "." + std::to_string(minor) +
                                 ((profile & GL_CONTEXT_CORE_PROFILE_BIT) ? " core" : " (not core)") +
                                 " from " + rendererName_ + "; fxport needs 4.1 core or newer");
    }
    if (debug) {
        glEnable(GL_DEBUG_OUTPUT);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);  // messages arrive inside the call that caused them
        glDebugMessageCallback(printDebugMessage, nullptr);
        glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DEBUG_SEVERITY_NOTIFICATION, 0, nullptr,
                              GL_FALSE);
    }
}

std::unique_ptr<GraphicsContext> GraphicsContext::create(const ContextDesc& descIn) {
    ContextDesc desc = descIn;
    if (desc.width <= 0) desc.width = 64;
    if (desc.height <= 0) desc.height = 64;
    if (desc.title.empty()) desc.title = "fxport";

    std::unique_ptr<ContextBase> context;
    switch (desc.platform) {
        case Platform::OSMesa: context = createOSMesaContext(desc); break;
#ifdef FXPORT_HAVE_EGL
        case Platform::EGL: context = createEGLContext(desc); break;
#endif
#ifdef FXPORT_HAVE_GLFW
        case Platform::GLFW: context = createGLFWContext(desc); break;
#endif
        default:
            throw std::runtime_error(std::string("platform '") + platformName(desc.platform) +
                                     "' is not built into fxport (available: " +
                                     joinedNames(availablePlatforms()) + ")");
    }
    context->initialiseGL(desc.debug);
    return context;
}

const char* platformName(Platform platform) {
    switch (platform) {
        case Platform::OSMesa: return "osmesa";
        case Platform::EGL: return "egl";
        case Platform::GLFW: return "glfw";
    }
    return "unknown";
}

Platform platformFromString(const std::string& name) {
    std::string lower = name;
    std::transform(lower.begin(), lower.end(), lower.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    for (Platform p : {Platform::OSMesa, Platform::EGL, Platform::GLFW}) {
        if (lower == platformName(p)) return p;
    }
    throw std::runtime_error("unknown platform '" + name + "' (valid: osmesa, egl, glfw; built in: " +
                             joinedNames(availablePlatforms()) + ")");
}

bool primaryDisplayModes(std::vector<DisplayModeInfo>& modes, DisplayModeInfo& current) {
#ifdef FXPORT_HAVE_GLFW
    return glfwDisplayModes(modes, current);
#else
    (void)modes;
    (void)current;
    return false;
#endif
}

std::vector<Platform> availablePlatforms() {
    std::vector<Platform> platforms{Platform::OSMesa};
#ifdef FXPORT_HAVE_EGL
    platforms.push_back(Platform::EGL);
#endif
#ifdef FXPORT_HAVE_GLFW
    platforms.push_back(Platform::GLFW);
#endif
    return platforms;
}

Platform defaultPlatform() {
    const char* value = std::getenv("FXPORT_PLATFORM");
    if (value == nullptr || *value == '\0') return Platform::OSMesa;
    try {
        return platformFromString(value);
    } catch (const std::runtime_error& e) {
        throw std::runtime_error(std::string("FXPORT_PLATFORM: ") + e.what());
    }
}

}  // namespace fxport::platform
