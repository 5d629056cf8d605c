// Game, GraphicsDeviceManager and GameTime: the part of XNA's Game class the ported demos use.
// XNA's Game.Run() owns the loop; here the loop is fxdemo's, so that it can run a fixed number of
// frames headless: Start() creates the device and runs Initialize (which, as in XNA, calls
// LoadContent), Tick() runs one Update and one Draw with a fixed 1/60 s step (XNA's IsFixedTimeStep
// default) and presents.
#pragma once

#include <memory>
#include <string>

#include "common/content_manager.h"
#include "fxport/graphics.h"

namespace fxport::demo {

struct GameTime {
    double ElapsedGameTimeSeconds = 0;
    double TotalGameTimeSeconds = 0;
};

// The back buffer the game asks for, and (fxport) where the GL context comes from.
struct GraphicsDeviceManager {
    int PreferredBackBufferWidth = 800;
    int PreferredBackBufferHeight = 480;
    // fxport: "osmesa" (headless, CPU), "egl" (headless, GPU) or "glfw" (window); empty (games
    // driven by tests): $FXPORT_PLATFORM, else osmesa. See PresentationParameters::platform.
    std::string platform;
};

class Game {
public:
    virtual ~Game();
    Game(const Game&) = delete;
    Game& operator=(const Game&) = delete;

    // Creates the GraphicsDevice from `graphics`, then Initialize() (which calls LoadContent()).
    void Start();
    // One frame: Update, Draw, Present.
    void Tick();

    // Asks the loop to stop after this frame.
    void Exit() { exitRequested_ = true; }
    bool ExitRequested() const { return exitRequested_; }
    int FrameCount() const { return frames_; }

    GraphicsDeviceManager graphics;
    // Named as in XNA (Game.GraphicsDevice); the type is spelled fxport::GraphicsDevice in games.
    fxport::GraphicsDevice* GraphicsDevice = nullptr;
    ContentManager Content;

protected:
    Game() = default;
    // XNA's Initialize() ends by calling LoadContent(); games call Game::Initialize() last.
    virtual void Initialize() { LoadContent(); }
    virtual void LoadContent() {}
    virtual void UnloadContent() {}
    virtual void Update(const GameTime& gameTime) { (void)gameTime; }
    virtual void Draw(const GameTime& gameTime) { (void)gameTime; }

private:
    std::unique_ptr<fxport::GraphicsDevice> device_;
    GameTime time_;
    bool exitRequested_ = false;
    int frames_ = 0;
};

}  // namespace fxport::demo
