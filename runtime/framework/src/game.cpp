// Game: device creation from the GraphicsDeviceManager, the run loop, and XNA's fixed / variable
// time step (the rules are in game.h).
#include "fxport/framework/game.h"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <string>
#include <thread>

#include "fxport/graphics/errors.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/platform/graphics_context.h"

namespace fxport {

namespace {

// XNA never lets one tick account for more than half a second (after a breakpoint or a stall).
const TimeSpan kMaxElapsedTime = TimeSpan::FromMilliseconds(500);
// Frames of lag (extra Updates) after which IsRunningSlowly is set.
constexpr int kSlowLagFrames = 5;

std::int64_t steadyClockTicks() {
    using namespace std::chrono;
    return duration_cast<duration<std::int64_t, std::ratio<1, TimeSpan::TicksPerSecond>>>(
               steady_clock::now().time_since_epoch())
        .count();
}

// $FXPORT_FRAMES: a positive number, else an error naming the variable and the value.
std::optional<int> framesFromEnvironment() {
    const char* value = std::getenv("FXPORT_FRAMES");
    if (!value || !*value) return std::nullopt;
    char* end = nullptr;
    const long n = std::strtol(value, &end, 10);
    if (*end != '\0' || n <= 0 || n > 1'000'000'000)
        throw ArgumentError(std::string("FXPORT_FRAMES='") + value + "': expected a positive number of frames");
    return int(n);
}

}  // namespace

Game::Game() { deviceManager_ = &graphics; }

Game::~Game() {
    // Components first (XNA's Game.Dispose): what they hold goes while the device still exists.
    Components.Clear();
    // Content (effects, models, textures) goes before the device that made it.
    Content.Unload();
    Content.setGraphicsDevice(nullptr);
}

void Game::Start() {
    if (started_) return;
    const GraphicsDeviceManager& manager = *deviceManager_;
    PresentationParameters parameters;
    parameters.BackBufferWidth = manager.PreferredBackBufferWidth;
    parameters.BackBufferHeight = manager.PreferredBackBufferHeight;
    parameters.BackBufferFormat = manager.PreferredBackBufferFormat;
    parameters.DepthStencilFormat = manager.PreferredDepthStencilFormat;
    parameters.platform = manager.platform;
    parameters.windowTitle = Window.Title;
    device_ = std::make_unique<fxport::GraphicsDevice>(parameters);
    GraphicsDevice = device_.get();
    Content.setGraphicsDevice(GraphicsDevice);
    started_ = true;
    deviceManager_->applyWindowSettings();
    applyWindowState();
    Initialize();
    // XNA's rule: from now on a component is initialized as it is added.
    Components.initializeOnAdd_ = true;
}

void Game::Initialize() {
    Components.initializeAdded();
    LoadContent();
}

void Game::Update(const GameTime& gameTime) { Components.update(gameTime); }

void Game::Draw(const GameTime& gameTime) { Components.draw(gameTime); }

bool Game::IsActive() const { return GraphicsDevice && device_->context().isFocused(); }

void Game::applyWindowState() {
    if (!GraphicsDevice) return;
    if (appliedMouseVisible_ != IsMouseVisible) {
        device_->context().setCursorVisible(IsMouseVisible);
        appliedMouseVisible_ = IsMouseVisible;
    }
    Window.applyChanges();
}

bool Game::usesRealClock() const {
    switch (Clock) {
    case GameClock::RealTime: return true;
    case GameClock::Simulated: return false;
    case GameClock::Automatic: break;
    }
    return GraphicsDevice && GraphicsDevice->context().platform() == platform::Platform::GLFW;
}

bool Game::windowClosed() const { return GraphicsDevice && device_->context().shouldClose(); }

void Game::Run() {
    Start();
    if (!FrameLimit) FrameLimit = framesFromEnvironment();
    while (!exitRequested_ && !windowClosed() && (!FrameLimit || frames_ < *FrameLimit)) Tick();
    // XNA's Game.Dispose unloads the components before the device goes (and the game's content with it).
    Components.unloadContent();
    UnloadContent();
}

void Game::RunOneFrame() {
    Start();
    Tick();
}

void Game::ResetElapsedTime() {
    accumulated_ = TimeSpan::Zero;
    lastClockTicks_ = -1;
    updateFrameLag_ = 0;
    time_.IsRunningSlowly = false;
}

void Game::Tick() {
    if (!started_) throw InvalidOperation("Game.Tick: the game has not started (call Run, RunOneFrame or Start first)");
    if (!usesRealClock()) {
        tick(TargetElapsedTime);
        return;
    }
    // Real time: XNA's fixed step waits for a whole step before it updates.
    for (;;) {
        const std::int64_t now = steadyClockTicks();
        if (lastClockTicks_ < 0) lastClockTicks_ = now - TargetElapsedTime.Ticks();
        const TimeSpan pending = accumulated_ + TimeSpan(now - lastClockTicks_);
        if (!IsFixedTimeStep || pending >= TargetElapsedTime) break;
        std::this_thread::sleep_for(std::chrono::microseconds((TargetElapsedTime - pending).Ticks() / 10));
    }
    const std::int64_t now = steadyClockTicks();
    const TimeSpan elapsed(now - lastClockTicks_);
    lastClockTicks_ = now;
    tick(elapsed);
}

void Game::Tick(TimeSpan elapsedRealTime) {
    if (!started_) throw InvalidOperation("Game.Tick: the game has not started (call Run, RunOneFrame or Start first)");
    tick(elapsedRealTime);
}

void Game::tick(TimeSpan elapsedRealTime) {
    applyWindowState();
    accumulated_ += elapsedRealTime;
    if (accumulated_ > kMaxElapsedTime) accumulated_ = kMaxElapsedTime;
    if (IsFixedTimeStep) {
        if (accumulated_ < TargetElapsedTime) return;  // nothing due yet: no Update, no Draw
        int steps = 0;
        time_.ElapsedGameTime = TargetElapsedTime;
        while (accumulated_ >= TargetElapsedTime && !exitRequested_) {
            accumulated_ -= TargetElapsedTime;
            time_.TotalGameTime += TargetElapsedTime;
            ++steps;
            ++updates_;
            Update(time_);
        }
        // Every Update beyond one per Draw is a frame of lag; a tick with exactly one pays one back.
        updateFrameLag_ += std::max(0, steps - 1);
        if (time_.IsRunningSlowly) {
            if (updateFrameLag_ == 0) time_.IsRunningSlowly = false;
        } else if (updateFrameLag_ >= kSlowLagFrames) {
            time_.IsRunningSlowly = true;
        }
        if (steps == 1 && updateFrameLag_ > 0) --updateFrameLag_;
        // Draw sees the game time of all the steps it follows.
        time_.ElapsedGameTime = TargetElapsedTime * steps;
    } else {
        time_.ElapsedGameTime = accumulated_;
        time_.TotalGameTime += accumulated_;
        accumulated_ = TimeSpan::Zero;
        ++updates_;
        Update(time_);
    }
    if (suppressDraw_) {
        suppressDraw_ = false;
        return;
    }
    if (BeginDraw()) {
        Draw(time_);
        EndDraw();
        ++frames_;
    }
}

void Game::EndDraw() { GraphicsDevice->Present(); }

}  // namespace fxport
