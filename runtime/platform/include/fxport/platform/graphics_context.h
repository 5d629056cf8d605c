// GL contexts for fxport, the same way on three platforms: OSMesa (headless, CPU; the default, needs
// no GPU and no display), EGL device (headless GPU) and GLFW (a window). No GL type appears here; code
// that calls GL includes the internal fxport/platform/gl.h, whose functions every context loads.
//
//   auto context = fxport::platform::GraphicsContext::create({});  // OSMesa, 64x64
//   ContextDesc desc;
//   desc.platform = defaultPlatform();                               // FXPORT_PLATFORM=egl: GPU
//   auto gpu = GraphicsContext::create(desc);
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace fxport::platform {

enum class Platform { OSMesa, EGL, GLFW };

struct ContextDesc {
    // Who provides the context. OSMesa renders on the CPU (llvmpipe) and works everywhere.
    Platform platform = Platform::OSMesa;
    // Size of the default framebuffer: the OSMesa buffer, the EGL pbuffer, the GLFW window. fxport
    // renders into FBOs, so headless users rarely care. Zero or less = 64.
    int width = 64;
    int height = 64;
    // Ask for a debug context and print GL debug messages (except notifications) to stderr.
    bool debug = false;
    // Window title (GLFW only). Empty = "fxport".
    std::string title;
    // swapBuffers waits for vertical blank (GLFW only; headless platforms have no display to wait for).
    bool vsync = false;
};

// Mouse position in window pixels (top-left origin) and buttons; all zero headless.
struct MouseInput {
    int x = 0, y = 0;
    bool left = false, right = false, middle = false;
    int scrollWheel = 0;  // accumulated, 120 per notch as in Windows/XNA
};

// A window's client area: its top-left corner on the desktop and its size, in screen units.
struct WindowBounds {
    int x = 0, y = 0, width = 0, height = 0;
};

// One gamepad in GLFW's standard mapping (an Xbox layout): buttons A, B, X, Y, LeftShoulder,
// RightShoulder, Back, Start, Guide, LeftThumb, RightThumb, DPadUp, DPadRight, DPadDown, DPadLeft;
// axes LeftX, LeftY, RightX, RightY (y down), LeftTrigger, RightTrigger (-1 released .. 1).
struct GamepadInput {
    bool connected = false;
    bool buttons[15] = {};
    float axes[6] = {0, 0, 0, 0, -1, -1};
};

// One GL context and its default framebuffer. Creating one makes it current and loads the GL
// functions. fxport drives GL from a single thread: contexts may be created, made current and
// destroyed only on that thread.
class GraphicsContext {
public:
    // Throws std::runtime_error if desc.platform is not built in (the message names it and lists
    // the available ones) or the context cannot be made (the message carries the OSMesa/EGL/GLFW
    // error), or the driver offers less than OpenGL 4.1 core.
    static std::unique_ptr<GraphicsContext> create(const ContextDesc& desc);

    GraphicsContext() = default;
    GraphicsContext(const GraphicsContext&) = delete;
    GraphicsContext& operator=(const GraphicsContext&) = delete;
    virtual ~GraphicsContext() = default;

    virtual Platform platform() const = 0;
    // Makes this context current on the calling thread (and reloads the GL function pointers if the
    // previous context came from another platform).
    virtual void makeCurrent() = 0;
    // Presents the window (GLFW); no-op on headless platforms.
    virtual void swapBuffers() = 0;
    // True once the user asked to close the window; always false headless.
    virtual bool shouldClose() const = 0;
    // Processes window events; no-op headless.
    virtual void pollEvents() = 0;
    // Keyboard and mouse of the window (GLFW); always up/zero headless. Keys are Windows
    // virtual-key codes, which are XNA's Keys values ('A' = 65, F1 = 112, Escape = 27 ...).
    virtual bool isKeyDown(int virtualKey) const = 0;
    virtual MouseInput mouse() const = 0;
    // Gamepad `index` (0..3); not connected headless or when none is plugged in.
    virtual GamepadInput gamepad(int index) const = 0;
    // Moves the pointer (window pixels); no-op headless.
    virtual void setMousePosition(int x, int y) = 0;
    // Size of the default framebuffer in pixels (a window's current size).
    virtual int width() const = 0;
    virtual int height() const = 0;
    // The window settings XNA's Game, GameWindow and GraphicsDeviceManager change while a game runs.
    // Headless there is no window, pointer or display: the setters do nothing, isFocused() is true
    // and clientBounds() is {0, 0, width(), height()}.
    virtual void setTitle(const std::string& title) = 0;
    virtual void setCursorVisible(bool visible) = 0;
    virtual void setResizable(bool resizable) = 0;
    // Full screen: the primary monitor at its current video mode (the back buffer is scaled into
    // it, as into a window); false restores the window's earlier position and size.
    virtual void setFullScreen(bool fullScreen) = 0;
    // Whether swapBuffers waits for vertical blank (ContextDesc::vsync, changed later).
    virtual void setVSync(bool vsync) = 0;
    virtual bool isFocused() const = 0;
    virtual WindowBounds clientBounds() const = 0;
    // GL_RENDERER and GL_VERSION, e.g. "llvmpipe (LLVM 15.0.6, 256 bits) / 4.5 (Core Profile) Mesa 22.3.6".
    virtual std::string rendererName() const = 0;
};

// A monitor's video mode.
struct DisplayModeInfo {
    int width = 0, height = 0, refreshRate = 0;
};
// The primary monitor's modes and, in `current`, the mode it runs in, where a display is reachable
// (GLFW built in and a monitor found); false otherwise (headless: no monitor).
bool primaryDisplayModes(std::vector<DisplayModeInfo>& modes, DisplayModeInfo& current);

// "osmesa", "egl", "glfw" (case-insensitive). Throws std::runtime_error listing the valid names.
Platform platformFromString(const std::string& name);
// The lower-case name that platformFromString accepts.
const char* platformName(Platform platform);
// The platforms built into this library (OSMesa always). Whether a context can really be made
// (a GPU for EGL, a display for GLFW) is only known by trying: create() throws with the reason.
std::vector<Platform> availablePlatforms();
// The platform named by the environment variable FXPORT_PLATFORM (osmesa|egl|glfw); OSMesa when it
// is unset or empty. Throws std::runtime_error for an unknown name rather than guessing.
Platform defaultPlatform();

}  // namespace fxport::platform
