#include "pointlights/game1.h"

namespace DeferredLighting {

Game1::Game1() {
    Content.RootDirectory = FXPORT_CONTENT_DIR;
    // fxport: the effects are compiled from their sources (hlsl/zima-lights), not from a content project.
    Content.EffectDirectory = FXPORT_HLSL_DIR "/zima-lights";
    graphics.PreferredBackBufferWidth = 800;
    graphics.PreferredBackBufferHeight = 600;
}

void Game1::Initialize() {
    camera = std::make_unique<Camera>(float(graphics.PreferredBackBufferWidth) / float(graphics.PreferredBackBufferHeight));
    camera->cameraArc = demo.cameraArc;
    camera->cameraRotation = demo.cameraRotation;
    camera->cameraDistance = demo.cameraDistance;
    camera->UpdateView();
    scene = std::make_unique<Scene>();
    Game::Initialize();
}

void Game1::LoadContent() {
    quadRenderer = std::make_unique<QuadRenderer>(*GraphicsDevice);
    renderer = std::make_unique<DeferredRenderer>(*GraphicsDevice, Content, *camera, *quadRenderer, *scene, demo.quality);
}

void Game1::Update(const GameTime& gameTime) {
    previousK = currentK;
    currentK = Keyboard::GetState();
    // Allows the game to exit
    if (currentK.IsKeyUp(Keys::Escape) && previousK.IsKeyDown(Keys::Escape)) this->Exit();
    camera->Update(gameTime, currentK);
    Game::Update(gameTime);
}

void Game1::Draw(const GameTime& gameTime) {
    GameTime time = gameTime;
    if (demo.time) time.TotalGameTime = TimeSpan::FromSeconds(*demo.time);
    renderer->Draw(time);
    Game::Draw(gameTime);
}

}  // namespace DeferredLighting
