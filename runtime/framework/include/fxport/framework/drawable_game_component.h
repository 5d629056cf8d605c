// DrawableGameComponent: a GameComponent that also draws (XNA's DrawableGameComponent). Its
// Initialize loads its content once (LoadContent), Game::Draw (a C# base.Draw(gameTime)) draws the
// Visible ones by DrawOrder, and when Game::Run ends its UnloadContent runs (whether or not it was
// ever initialized), before the game's own UnloadContent, as XNA's Game.Dispose does.
//
//   class FrameRateCounter : public fxport::DrawableGameComponent {
//   public:
//       explicit FrameRateCounter(fxport::Game* game) : DrawableGameComponent(game) {}
//       void Draw(const fxport::GameTime& gameTime) override { ... GraphicsDevice()->... }
//   protected:
//       void LoadContent() override { font = Game()->Content.Load<fxport::SpriteFont>("Font"); }
//   };
#pragma once

#include "fxport/framework/game_component.h"

namespace fxport {

class GraphicsDevice;

class DrawableGameComponent : public GameComponent {
public:
    explicit DrawableGameComponent(fxport::Game* game) : GameComponent(game) {}

    // The game's device: nullptr before the game has started (rule 1: read-only, so a method).
    fxport::GraphicsDevice* GraphicsDevice() const;

    // XNA's defaults: drawn, in the order components were added (DrawOrder 0 for all).
    bool Visible = true;
    int DrawOrder = 0;

    // Calls LoadContent the first time (an override calls DrawableGameComponent::Initialize()).
    void Initialize() override;
    virtual void Draw(const GameTime& gameTime) { (void)gameTime; }

protected:
    virtual void LoadContent() {}
    virtual void UnloadContent() {}

private:
    friend class GameComponentCollection;  // calls UnloadContent when Game::Run ends

    bool contentLoaded_ = false;
};

}  // namespace fxport
