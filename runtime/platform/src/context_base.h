// Internal: what every platform's context shares (current-context bookkeeping, GL loading, version
// check, debug hook), and the factory of each platform. Includes no GL or window-system header, so
// each platform's .cpp can include its own (osmesa.h drags in <GL/gl.h>, which gl.h must not meet).
#pragma once

#include <memory>
#include <string>

#include "fxport/platform/graphics_context.h"

namespace fxport::platform {

class ContextBase : public GraphicsContext {
public:
    using ProcLoader = void* (*)(const char*);

    Platform platform() const override { return platform_; }
    void makeCurrent() override;
    void swapBuffers() override {}
    bool shouldClose() const override { return false; }
    void pollEvents() override {}
    bool isKeyDown(int) const override { return false; }
    MouseInput mouse() const override { return {}; }
    GamepadInput gamepad(int) const override { return {}; }
    void setMousePosition(int, int) override {}
    void setTitle(const std::string&) override {}
    void setCursorVisible(bool) override {}
    void setResizable(bool) override {}
    void setFullScreen(bool) override {}
    void setVSync(bool) override {}
    bool isFocused() const override { return true; }
    WindowBounds clientBounds() const override { return {0, 0, width(), height()}; }
    int width() const override { return width_; }
    int height() const override { return height_; }
    std::string rendererName() const override { return rendererName_; }

    // Run by create() once the object is fully built, so that a throw here still runs the platform
    // destructor: makes current, loads GL, checks for >= 4.1 core, installs the debug hook.
    void initialiseGL(bool debug);

protected:
    ContextBase(Platform platform, ProcLoader loader, int width, int height);
    // Platform destructors call this first, while their native context still exists.
    void releaseIfCurrent();

    virtual void bindNative() = 0;    // make the native context current; throws on failure
    virtual void unbindNative() = 0;  // leave no context of this platform current

private:
    Platform platform_;
    ProcLoader loader_;
    int width_;
    int height_;
    std::string rendererName_;
};

// Each throws std::runtime_error carrying the native error. Defined in <platform>_context.cpp.
std::unique_ptr<ContextBase> createOSMesaContext(const ContextDesc& desc);
#ifdef FXPORT_HAVE_EGL
std::unique_ptr<ContextBase> createEGLContext(const ContextDesc& desc);
#endif
#ifdef FXPORT_HAVE_GLFW
std::unique_ptr<ContextBase> createGLFWContext(const ContextDesc& desc);
bool glfwDisplayModes(std::vector<DisplayModeInfo>& modes, DisplayModeInfo& current);  // primaryDisplayModes
#endif

}  // namespace fxport::platform
