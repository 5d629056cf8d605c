// GraphicsDeviceManager: the back buffer a Game asks for, and the switch between headless and a
// window. As in XNA, a game makes one with itself as owner (`graphics = new
// GraphicsDeviceManager(this)` -> `fxport::GraphicsDeviceManager graphics{this};`) and sets the
// Preferred* fields, IsFullScreen and the rest before Run; after that, ApplyChanges() applies them.
// A Game also has a manager of its own (Game::graphics), used when the game declares none.
#pragma once

#include <string>

#include "fxport/framework/graphics_profile.h"
#include "fxport/graphics/surface_format.h"

namespace fxport {

class Game;
class GraphicsDevice;

class GraphicsDeviceManager {
public:
    // Becomes `game`'s device manager (the last one made for a game wins, as the last service
    // registered would; Game::graphics is made first).
    explicit GraphicsDeviceManager(Game* game);
    ~GraphicsDeviceManager();
    GraphicsDeviceManager(const GraphicsDeviceManager&) = delete;
    // Copies the settings (the fields); each manager stays with its own game.
    GraphicsDeviceManager& operator=(const GraphicsDeviceManager& other);

    // XNA 4's defaults.
    int PreferredBackBufferWidth = 800;
    int PreferredBackBufferHeight = 480;
    SurfaceFormat PreferredBackBufferFormat = SurfaceFormat::Color;
    DepthFormat PreferredDepthStencilFormat = DepthFormat::Depth24;
    // Read when the device is made and by ApplyChanges (XNA's defaults). Full screen, in a window
    // (GLFW), fills the primary monitor at its current mode and scales the back buffer into it;
    // headless there is no screen and nothing changes. The vertical retrace is the window's swap
    // interval; headless nothing waits for it.
    bool IsFullScreen = false;
    bool SynchronizeWithVerticalRetrace = true;
    // fxport's back buffer is never multisampled: true prints a warning (once per manager).
    bool PreferMultiSampling = false;
    // Recorded only: the device has every HiDef feature and enforces no Reach limit (graphics_profile.h).
    fxport::GraphicsProfile GraphicsProfile = fxport::GraphicsProfile::Reach;
    // fxport: where the GL context comes from: "osmesa" (headless, CPU), "egl" (headless, GPU) or
    // "glfw" (a window). Empty: $FXPORT_PLATFORM, else osmesa -- headless unless asked.
    std::string platform;

    // The device, once the game has started (Game::Run / Start); nullptr before.
    fxport::GraphicsDevice* GraphicsDevice() const;
    // Applies the Preferred* fields to the running device: the back buffer is made again at the new
    // size and format (its contents are lost, as after XNA's device reset). Before the game starts
    // it does nothing (Run reads the fields). A window keeps its size (fxport: the back buffer is
    // scaled into it at Present).
    void ApplyChanges();
    // XNA's ToggleFullScreen: flips IsFullScreen and applies the changes at once (ApplyChanges).
    void ToggleFullScreen();

private:
    friend class Game;
    // Hands IsFullScreen and SynchronizeWithVerticalRetrace to the device's window; warns about
    // PreferMultiSampling. Run when the device is made and by ApplyChanges.
    void applyWindowSettings();

    Game* game_;
    bool warnedMultiSampling_ = false;
};

}  // namespace fxport
