#include "common/game.h"

namespace fxport::demo {

Game::~Game() {
    // Content (effects, models, textures) goes before the device that made it.
    Content.Unload();
}

void Game::Start() {
    PresentationParameters parameters;
    parameters.BackBufferWidth = graphics.PreferredBackBufferWidth;
    parameters.BackBufferHeight = graphics.PreferredBackBufferHeight;
    parameters.platform = graphics.platform;
    parameters.windowTitle = "fxdemo";
    device_ = std::make_unique<fxport::GraphicsDevice>(parameters);
    GraphicsDevice = device_.get();
    Content.setGraphicsDevice(GraphicsDevice);
    Initialize();
}

void Game::Tick() {
    // A fixed step of 1/60 s, as XNA's default IsFixedTimeStep.
    time_.ElapsedGameTimeSeconds = 1.0 / 60.0;
    time_.TotalGameTimeSeconds += time_.ElapsedGameTimeSeconds;
    Update(time_);
    Draw(time_);
    GraphicsDevice->Present();
    ++frames_;
}

}  // namespace fxport::demo
