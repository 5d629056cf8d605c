// GraphicsDeviceManager: registration with its Game, ApplyChanges (a device Reset) and the window
// settings (full screen, vertical retrace).
#include "fxport/framework/graphics_device_manager.h"

#include <cstdio>

#include "fxport/framework/game.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/platform/graphics_context.h"

namespace fxport {

GraphicsDeviceManager::GraphicsDeviceManager(Game* game) : game_(game) {
    if (game_) game_->deviceManager_ = this;
}

GraphicsDeviceManager::~GraphicsDeviceManager() {
    // A game's own manager (Game::graphics) outlives any a derived game made.
    if (game_ && game_->deviceManager_ == this && this != &game_->graphics) game_->deviceManager_ = &game_->graphics;
}

GraphicsDeviceManager& GraphicsDeviceManager::operator=(const GraphicsDeviceManager& other) {
    PreferredBackBufferWidth = other.PreferredBackBufferWidth;
    PreferredBackBufferHeight = other.PreferredBackBufferHeight;
    PreferredBackBufferFormat = other.PreferredBackBufferFormat;
    PreferredDepthStencilFormat = other.PreferredDepthStencilFormat;
    IsFullScreen = other.IsFullScreen;
    SynchronizeWithVerticalRetrace = other.SynchronizeWithVerticalRetrace;
    PreferMultiSampling = other.PreferMultiSampling;
    GraphicsProfile = other.GraphicsProfile;
    platform = other.platform;
    return *this;
}

fxport::GraphicsDevice* GraphicsDeviceManager::GraphicsDevice() const { return game_ ? game_->GraphicsDevice : nullptr; }

void GraphicsDeviceManager::ApplyChanges() {
    fxport::GraphicsDevice* device = GraphicsDevice();
    if (!device) return;
    PresentationParameters parameters = device->PresentationParameters();
    parameters.BackBufferWidth = PreferredBackBufferWidth;
    parameters.BackBufferHeight = PreferredBackBufferHeight;
    parameters.BackBufferFormat = PreferredBackBufferFormat;
    parameters.DepthStencilFormat = PreferredDepthStencilFormat;
    device->Reset(parameters);
    applyWindowSettings();
}

void GraphicsDeviceManager::ToggleFullScreen() {
    IsFullScreen = !IsFullScreen;
    ApplyChanges();
}

void GraphicsDeviceManager::applyWindowSettings() {
    fxport::GraphicsDevice* device = GraphicsDevice();
    if (!device) return;
    device->context().setFullScreen(IsFullScreen);
    device->context().setVSync(SynchronizeWithVerticalRetrace);
    // Said once, not silently dropped: the game may rely on smooth edges that it will not get.
    if (PreferMultiSampling && !warnedMultiSampling_) {
        std::fprintf(stderr, "fxport: warning: GraphicsDeviceManager.PreferMultiSampling: fxport's back buffer is not "
                             "multisampled; drawing without multisampling\n");
        warnedMultiSampling_ = true;
    }
}

}  // namespace fxport
