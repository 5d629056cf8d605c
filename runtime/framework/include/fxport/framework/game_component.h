// GameComponent: XNA's reusable piece of a game's Update (a frame counter, an input handler) that
// the game keeps in Game::Components. Derive from it and override Initialize / Update:
//
//   class InputHandler : public fxport::GameComponent {
//   public:
//       explicit InputHandler(fxport::Game* game) : GameComponent(game) {}
//       void Update(const fxport::GameTime& gameTime) override { ... }
//   };
//   Components.Add(new InputHandler(this));    // C#: Components.Add(new InputHandler(this));
//
// Game::Initialize initializes the components added so far, one added after that is initialized
// when it is added, and Game::Update (a C# base.Update(gameTime)) updates the Enabled ones by
// UpdateOrder: game_component_collection.h has XNA's rules. Inside a component, as in C#, Game() is
// the game; the type is spelled fxport::Game there (the member hides it).
#pragma once

namespace fxport {

class Game;
struct GameTime;

class GameComponent {
public:
    explicit GameComponent(fxport::Game* game) : game_(game) {}
    virtual ~GameComponent() = default;
    GameComponent(const GameComponent&) = delete;
    GameComponent& operator=(const GameComponent&) = delete;

    fxport::Game* Game() const { return game_; }

    // XNA's defaults: updated, in the order components were added (UpdateOrder 0 for all).
    // Read at every Game::Update, so a change takes effect at the next one.
    bool Enabled = true;
    int UpdateOrder = 0;

    virtual void Initialize() {}
    virtual void Update(const GameTime& gameTime) { (void)gameTime; }

private:
    fxport::Game* game_;
};

}  // namespace fxport
