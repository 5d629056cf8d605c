// GLFW: a window with a 4.5 core context, for interactive runs (--window). The GLFWwindow stays in
// this file; keyboard and mouse input will be added here when the demos need them.
#define GLFW_INCLUDE_NONE  // GLFW must not pull in <GL/gl.h>: GL comes from fxport/platform/gl.h only
#include <GLFW/glfw3.h>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <utility>

#include "context_base.h"

namespace fxport::platform {
namespace {

void* glfwProcAddress(const char* name) { return reinterpret_cast<void*>(glfwGetProcAddress(name)); }

std::string lastGlfwError() {
    const char* description = nullptr;
    const int code = glfwGetError(&description);
    if (code == GLFW_NO_ERROR) return "no GLFW error reported";
    char hex[16];
    std::snprintf(hex, sizeof hex, "0x%X", static_cast<unsigned>(code));
    return std::string(description != nullptr ? description : "?") + " (GLFW error " + hex + ")";
}

int g_liveWindows = 0;  // glfwInit with the first window, glfwTerminate after the last

class GLFWGraphicsContext final : public ContextBase {
public:
    explicit GLFWGraphicsContext(const ContextDesc& desc)
        : ContextBase(Platform::GLFW, glfwProcAddress, desc.width, desc.height), vsync_(desc.vsync) {
        if (g_liveWindows == 0 && !glfwInit()) throw std::runtime_error("glfw: glfwInit failed: " + lastGlfwError());
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, desc.debug ? GLFW_TRUE : GLFW_FALSE);
        glfwWindowHint(GLFW_DEPTH_BITS, 24);
        glfwWindowHint(GLFW_STENCIL_BITS, 8);
        window_ = glfwCreateWindow(desc.width, desc.height, desc.title.c_str(), nullptr, nullptr);
        if (window_ == nullptr) {
            const std::string why = lastGlfwError();
            if (g_liveWindows == 0) glfwTerminate();
            throw std::runtime_error("glfw: could not open a window with an OpenGL 4.5 core context: " + why);
        }
        ++g_liveWindows;
    }

    ~GLFWGraphicsContext() override {
        releaseIfCurrent();
        glfwDestroyWindow(window_);
        if (--g_liveWindows == 0) glfwTerminate();
    }

    void swapBuffers() override { glfwSwapBuffers(window_); }
    bool shouldClose() const override { return glfwWindowShouldClose(window_) != 0; }
    void pollEvents() override { glfwPollEvents(); }
    // The window may have been resized (and on HiDPI screens pixels differ from screen units).
    int width() const override { return framebufferSize().first; }
    int height() const override { return framebufferSize().second; }

private:
    std::pair<int, int> framebufferSize() const {
        int w = 0, h = 0;
        glfwGetFramebufferSize(window_, &w, &h);
        return {w, h};
    }

    void bindNative() override {
        glfwMakeContextCurrent(window_);
        if (!swapIntervalSet_) {  // the swap interval belongs to the current context: set it once, here
            glfwSwapInterval(vsync_ ? 1 : 0);
            swapIntervalSet_ = true;
        }
    }
    void unbindNative() override { glfwMakeContextCurrent(nullptr); }

    GLFWwindow* window_ = nullptr;
    bool vsync_;
    bool swapIntervalSet_ = false;
};

}  // namespace

std::unique_ptr<ContextBase> createGLFWContext(const ContextDesc& desc) {
    return std::make_unique<GLFWGraphicsContext>(desc);
}

}  // namespace fxport::platform
