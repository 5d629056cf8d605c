// GraphicsDeviceManager: registration with its Game and ApplyChanges (a device Reset).
#include "fxport/framework/graphics_device_manager.h"

#include "fxport/framework/game.h"
#include "fxport/graphics/graphics_device.h"

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
}

}  // namespace fxport
