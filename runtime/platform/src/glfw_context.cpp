// GLFW: a window with a 4.5 core context, for interactive runs (--window). The GLFWwindow stays in
// this file, with keyboard, mouse and gamepad input.
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

// Windows virtual-key code (XNA's Keys) -> GLFW key. Letters, digits and space coincide.
int glfwKeyFor(int vk) {
    if ((vk >= 'A' && vk <= 'Z') || (vk >= '0' && vk <= '9') || vk == ' ') return vk;
    if (vk >= 0x70 && vk <= 0x7B) return GLFW_KEY_F1 + (vk - 0x70);        // F1..F12
    if (vk >= 0x60 && vk <= 0x69) return GLFW_KEY_KP_0 + (vk - 0x60);      // NumPad0..9
    if (vk >= 0x7C && vk <= 0x87) return GLFW_KEY_F13 + (vk - 0x7C);        // F13..F24
    switch (vk) {
    case 0x14: return GLFW_KEY_CAPS_LOCK;
    case 0x23: return GLFW_KEY_END;
    case 0x24: return GLFW_KEY_HOME;
    case 0x2C: return GLFW_KEY_PRINT_SCREEN;
    case 0x2D: return GLFW_KEY_INSERT;
    case 0x2E: return GLFW_KEY_DELETE;
    case 0x5B: return GLFW_KEY_LEFT_SUPER;
    case 0x5C: return GLFW_KEY_RIGHT_SUPER;
    case 0x5D: return GLFW_KEY_MENU;
    case 0x6A: return GLFW_KEY_KP_MULTIPLY;
    case 0x6B: return GLFW_KEY_KP_ADD;
    case 0x6D: return GLFW_KEY_KP_SUBTRACT;
    case 0x6E: return GLFW_KEY_KP_DECIMAL;
    case 0x6F: return GLFW_KEY_KP_DIVIDE;
    case 0x90: return GLFW_KEY_NUM_LOCK;
    case 0x91: return GLFW_KEY_SCROLL_LOCK;
    case 0xBA: return GLFW_KEY_SEMICOLON;
    case 0xBC: return GLFW_KEY_COMMA;
    case 0xBE: return GLFW_KEY_PERIOD;
    case 0xBF: return GLFW_KEY_SLASH;
    case 0xC0: return GLFW_KEY_GRAVE_ACCENT;
    case 0xDB: return GLFW_KEY_LEFT_BRACKET;
    case 0xDC: return GLFW_KEY_BACKSLASH;
    case 0xDD: return GLFW_KEY_RIGHT_BRACKET;
    case 0xDE: return GLFW_KEY_APOSTROPHE;
    case 0xE2: return GLFW_KEY_WORLD_1;
    case 0x13: return GLFW_KEY_PAUSE;
    case 0x1B: return GLFW_KEY_ESCAPE;
    case 0x0D: return GLFW_KEY_ENTER;
    case 0x09: return GLFW_KEY_TAB;
    case 0x08: return GLFW_KEY_BACKSPACE;
    case 0x25: return GLFW_KEY_LEFT;
    case 0x26: return GLFW_KEY_UP;
    case 0x27: return GLFW_KEY_RIGHT;
    case 0x28: return GLFW_KEY_DOWN;
    case 0x21: return GLFW_KEY_PAGE_UP;
    case 0x22: return GLFW_KEY_PAGE_DOWN;
    case 0xA0: return GLFW_KEY_LEFT_SHIFT;
    case 0xA1: return GLFW_KEY_RIGHT_SHIFT;
    case 0xA2: return GLFW_KEY_LEFT_CONTROL;
    case 0xA3: return GLFW_KEY_RIGHT_CONTROL;
    case 0xA4: return GLFW_KEY_LEFT_ALT;
    case 0xA5: return GLFW_KEY_RIGHT_ALT;
    case 0xBB: return GLFW_KEY_EQUAL;
    case 0xBD: return GLFW_KEY_MINUS;
    default: return GLFW_KEY_UNKNOWN;
    }
}

double g_scroll = 0;  // accumulated by the scroll callback (one window is the usual case)

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
        glfwSetScrollCallback(window_, [](GLFWwindow*, double, double dy) { g_scroll += dy; });
    }

    ~GLFWGraphicsContext() override {
        releaseIfCurrent();
        glfwDestroyWindow(window_);
        if (--g_liveWindows == 0) glfwTerminate();
    }

    void swapBuffers() override { glfwSwapBuffers(window_); }
    bool shouldClose() const override { return glfwWindowShouldClose(window_) != 0; }
    void pollEvents() override { glfwPollEvents(); }
    bool isKeyDown(int virtualKey) const override {
        int key = glfwKeyFor(virtualKey);
        return key != GLFW_KEY_UNKNOWN && glfwGetKey(window_, key) == GLFW_PRESS;
    }
    void setMousePosition(int x, int y) override { glfwSetCursorPos(window_, x, y); }
    GamepadInput gamepad(int index) const override {
        GamepadInput g;
        GLFWgamepadstate state;
        if (index < 0 || index > GLFW_JOYSTICK_LAST || !glfwJoystickIsGamepad(GLFW_JOYSTICK_1 + index) ||
            !glfwGetGamepadState(GLFW_JOYSTICK_1 + index, &state))
            return g;
        g.connected = true;
        for (int b = 0; b < 15; ++b) g.buttons[b] = state.buttons[b] == GLFW_PRESS;
        for (int a = 0; a < 6; ++a) g.axes[a] = state.axes[a];
        return g;
    }
    MouseInput mouse() const override {
        MouseInput m;
        double x = 0, y = 0;
        glfwGetCursorPos(window_, &x, &y);
        m.x = int(x);
        m.y = int(y);
        m.left = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_LEFT) == GLFW_PRESS;
        m.right = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS;
        m.middle = glfwGetMouseButton(window_, GLFW_MOUSE_BUTTON_MIDDLE) == GLFW_PRESS;
        m.scrollWheel = int(g_scroll * 120);
        return m;
    }
    void setTitle(const std::string& title) override { glfwSetWindowTitle(window_, title.c_str()); }
    void setCursorVisible(bool visible) override {
        glfwSetInputMode(window_, GLFW_CURSOR, visible ? GLFW_CURSOR_NORMAL : GLFW_CURSOR_HIDDEN);
    }
    void setResizable(bool resizable) override {
        glfwSetWindowAttrib(window_, GLFW_RESIZABLE, resizable ? GLFW_TRUE : GLFW_FALSE);
    }
    void setFullScreen(bool fullScreen) override;
    void setVSync(bool vsync) override {
        vsync_ = vsync;
        // The swap interval belongs to the current context: now if this one is, else at its next bind.
        if (glfwGetCurrentContext() == window_) glfwSwapInterval(vsync_ ? 1 : 0);
        else swapIntervalSet_ = false;
    }
    bool isFocused() const override { return glfwGetWindowAttrib(window_, GLFW_FOCUSED) != 0; }
    WindowBounds clientBounds() const override {
        WindowBounds b;
        glfwGetWindowPos(window_, &b.x, &b.y);
        glfwGetWindowSize(window_, &b.width, &b.height);
        return b;
    }
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
    WindowBounds windowed_;  // where the window was before it went full screen
    bool vsync_;
    bool swapIntervalSet_ = false;
};

// FNA's "desktop" full screen: the monitor keeps its video mode (no mode switch to the back buffer's
// size as XNA made), the back buffer is scaled into it at Present.
void GLFWGraphicsContext::setFullScreen(bool fullScreen) {
    if ((glfwGetWindowMonitor(window_) != nullptr) == fullScreen) return;
    if (!fullScreen) {
        glfwSetWindowMonitor(window_, nullptr, windowed_.x, windowed_.y, windowed_.width, windowed_.height, GLFW_DONT_CARE);
        return;
    }
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    const GLFWvidmode* mode = monitor != nullptr ? glfwGetVideoMode(monitor) : nullptr;
    if (mode == nullptr) {
        std::fprintf(stderr, "fxport: warning: GraphicsDeviceManager.IsFullScreen: no monitor to fill (%s); staying in a window\n",
                     lastGlfwError().c_str());
        return;
    }
    windowed_ = clientBounds();
    glfwSetWindowMonitor(window_, monitor, 0, 0, mode->width, mode->height, mode->refreshRate);
}

}  // namespace

std::unique_ptr<ContextBase> createGLFWContext(const ContextDesc& desc) {
    return std::make_unique<GLFWGraphicsContext>(desc);
}

// GLFW is initialised for the question only when no window holds it (and terminated after).
bool glfwDisplayModes(std::vector<DisplayModeInfo>& modes, DisplayModeInfo& current) {
    const bool own = g_liveWindows == 0;
    if (own && !glfwInit()) return false;
    GLFWmonitor* monitor = glfwGetPrimaryMonitor();
    const GLFWvidmode* now = monitor != nullptr ? glfwGetVideoMode(monitor) : nullptr;
    if (now != nullptr) {
        current = {now->width, now->height, now->refreshRate};
        int count = 0;
        const GLFWvidmode* all = glfwGetVideoModes(monitor, &count);
        for (int i = 0; i < count; ++i) modes.push_back({all[i].width, all[i].height, all[i].refreshRate});
    }
    if (own) glfwTerminate();
    return now != nullptr;
}

}  // namespace fxport::platform
