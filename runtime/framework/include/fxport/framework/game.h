// Game: XNA 4's Game class. A game derives from it, overrides Initialize / LoadContent /
// UnloadContent / Update / Draw, and calls Run():
//
//   class Game1 : public fxport::Game {
//       fxport::GraphicsDeviceManager graphics{this};
//       fxport::SpriteBatch* spriteBatch = nullptr; ...
//   public:
//       Game1() { Content.RootDirectory = "Content"; }
//   protected:
//       void LoadContent() override { effect = Content.Load<fxport::Effect>("Effects/Glow"); }
//       void Update(const fxport::GameTime& gameTime) override { ... Exit(); ... }
//       void Draw(const fxport::GameTime& gameTime) override { GraphicsDevice->Clear(Color::CornflowerBlue); ... }
//   };
//   int main() { Game1 game; game.Run(); }
//
// Run() makes the GraphicsDevice from the GraphicsDeviceManager (headless OSMesa unless the manager
// or $FXPORT_PLATFORM asks for "egl" or a "glfw" window), calls Initialize (whose base version
// initializes the Components and calls LoadContent), then ticks until Exit(), the window closes or
// FrameLimit frames have been drawn, and ends by unloading the drawable components, then
// UnloadContent.
//
// Time, as XNA (Tick): with IsFixedTimeStep (the default) every Update advances the game by
// TargetElapsedTime (default 1/60 s); a tick that finds less real time than that waits, one that
// finds more runs several Updates before one Draw (at most 500 ms worth), and GameTime.IsRunningSlowly
// is set after 5 frames of lag and cleared once it is gone. Without IsFixedTimeStep one Update with
// the real elapsed time runs per Draw. The real time comes from `Clock`: the steady clock in a
// window, and headless -- where nobody watches and runs must repeat -- exactly TargetElapsedTime
// per tick, without waiting (GameClock::Automatic).
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "fxport/framework/content_manager.h"
#include "fxport/framework/drawable_game_component.h"
#include "fxport/framework/game_component_collection.h"
#include "fxport/framework/game_service_container.h"
#include "fxport/framework/game_time.h"
#include "fxport/framework/game_window.h"
#include "fxport/framework/graphics_device_manager.h"
#include "fxport/framework/time_span.h"

namespace fxport {

class GraphicsDevice;

// Where Tick gets the real time that passed since the previous tick.
enum class GameClock {
    Automatic,  // RealTime in a window (GLFW), Simulated headless
    RealTime,   // std::chrono::steady_clock
    Simulated,  // exactly TargetElapsedTime per tick, no waiting: every run takes the same steps
};

class Game {
public:
    virtual ~Game();
    Game(const Game&) = delete;
    Game& operator=(const Game&) = delete;

    // XNA's Run: Start(), then Tick() until Exit(), the window closes or FrameLimit frames have been
    // drawn, then UnloadContent().
    void Run();
    // XNA's RunOneFrame: Start() if needed, then one Tick().
    void RunOneFrame();
    // XNA's Tick: waits (fixed step, real clock) until TargetElapsedTime has passed, runs the
    // Updates due and one Draw (BeginDraw / Draw / EndDraw, which presents). Start() first.
    void Tick();
    // fxport: one tick as if `elapsedRealTime` had passed since the previous one (no waiting):
    // how tests drive the fixed-step rules.
    void Tick(TimeSpan elapsedRealTime);
    // fxport: makes the GraphicsDevice and runs Initialize() (the start of XNA's Run), for hosts
    // that drive Tick() themselves. Does nothing the second time.
    void Start();

    // Asks the game to stop: Run returns after the current tick.
    void Exit() { exitRequested_ = true; }
    // XNA's ResetElapsedTime: the next tick sees no elapsed time (after a long load), and
    // IsRunningSlowly is cleared.
    void ResetElapsedTime();
    // XNA's SuppressDraw: the current tick skips Draw.
    void SuppressDraw() { suppressDraw_ = true; }

    // XNA's fixed time step switch and its step (default 1/60 s: 166667 ticks, as XNA).
    bool IsFixedTimeStep = true;
    TimeSpan TargetElapsedTime = TimeSpan::FromTicks(166667);
    // fxport: Run stops after this many frames (Draws) when set; $FXPORT_FRAMES sets it when the
    // game does not (so an unmodified game can run headless in a script or test).
    std::optional<int> FrameLimit;
    GameClock Clock = GameClock::Automatic;
    // XNA's default: the pointer is hidden over the window. Handed to the window at the next tick;
    // headless there is no pointer to show.
    bool IsMouseVisible = false;
    // Whether the window has the keyboard focus (XNA: the game is the foreground program). Always
    // true headless; false before the game has started.
    bool IsActive() const;

    // fxport: whether Exit() was called; frames drawn so far; the number of Update calls so far.
    bool ExitRequested() const { return exitRequested_; }
    int FrameCount() const { return frames_; }
    int UpdateCount() const { return updates_; }

    // The game's own device manager (fxport: XNA games make theirs in the constructor; a game that
    // does -- GraphicsDeviceManager graphics{this}; -- replaces this one).
    GraphicsDeviceManager graphics{this};
    // The manager Run uses: the last one made for this game.
    GraphicsDeviceManager& graphicsDeviceManager() { return *deviceManager_; }
    // Named as in XNA (Game.GraphicsDevice, Game.Content, Game.Window); the device type is spelled
    // fxport::GraphicsDevice inside a game. GraphicsDevice is nullptr until Start(); the game
    // owns it and keeps it until the Game is destroyed (after Content is unloaded).
    fxport::GraphicsDevice* GraphicsDevice = nullptr;
    ContentManager Content;
    GameWindow Window{*this};
    // XNA's Components and Services (game_component_collection.h, game_service_container.h).
    GameComponentCollection Components;
    GameServiceContainer Services;

protected:
    Game();
    // XNA's Initialize() initializes the Components added so far and ends by calling
    // LoadContent(); overrides call Game::Initialize() last.
    virtual void Initialize();
    virtual void LoadContent() {}
    virtual void UnloadContent() {}
    // Updates the Enabled components by UpdateOrder (what a C# base.Update(gameTime) does).
    virtual void Update(const GameTime& gameTime);
    // Return false to skip this frame's Draw and EndDraw.
    virtual bool BeginDraw() { return true; }
    // Draws the Visible drawable components by DrawOrder (a C# base.Draw(gameTime)).
    virtual void Draw(const GameTime& gameTime);
    // Presents the back buffer.
    virtual void EndDraw();

private:
    friend class GraphicsDeviceManager;
    void tick(TimeSpan elapsedRealTime);
    bool usesRealClock() const;
    bool windowClosed() const;
    // Hands IsMouseVisible and Window's fields to the window when they changed.
    void applyWindowState();

    GraphicsDeviceManager* deviceManager_ = nullptr;
    std::unique_ptr<fxport::GraphicsDevice> device_;
    GameTime time_;
    TimeSpan accumulated_;
    std::int64_t lastClockTicks_ = -1;  // steady clock, in TimeSpan ticks; -1 = not read yet
    int updateFrameLag_ = 0;
    std::optional<bool> appliedMouseVisible_;
    bool started_ = false;
    bool exitRequested_ = false;
    bool suppressDraw_ = false;
    int frames_ = 0;
    int updates_ = 0;
};

}  // namespace fxport
