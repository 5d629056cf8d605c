// fxport::Game: the run loop, XNA's fixed and variable time step (game.h), the device made from the
// GraphicsDeviceManager, ApplyChanges. Headless (OSMesa unless $FXPORT_PLATFORM); every game makes
// its own device.
#include <cstdlib>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fxport/framework.h"

namespace fxport {
namespace {

// Records what the game loop called, in order, with the GameTime it passed.
class RecordingGame : public Game {
public:
    std::vector<std::string> calls;
    std::vector<GameTime> updates, draws;
    int exitAfterUpdates = -1;

protected:
    void Initialize() override {
        calls.push_back("Initialize");
        Game::Initialize();
    }
    void LoadContent() override { calls.push_back("LoadContent"); }
    void UnloadContent() override { calls.push_back("UnloadContent"); }
    void Update(const GameTime& gameTime) override {
        updates.push_back(gameTime);
        if (int(updates.size()) == exitAfterUpdates) Exit();
    }
    void Draw(const GameTime& gameTime) override {
        draws.push_back(gameTime);
        GraphicsDevice->Clear(Color::CornflowerBlue);
    }
};

constexpr std::int64_t kStep = 166667;  // XNA's default TargetElapsedTime, in 100 ns ticks

TEST(Game, RunHeadlessTakesFixedStepsUntilTheFrameLimit) {
    RecordingGame game;
    game.graphics.PreferredBackBufferWidth = 32;
    game.graphics.PreferredBackBufferHeight = 16;
    game.FrameLimit = 4;
    game.Run();
    EXPECT_EQ(game.calls, (std::vector<std::string>{"Initialize", "LoadContent", "UnloadContent"}));
    ASSERT_EQ(game.updates.size(), 4u);
    ASSERT_EQ(game.draws.size(), 4u);
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(game.updates[i].ElapsedGameTime.Ticks(), kStep);
        EXPECT_EQ(game.updates[i].TotalGameTime.Ticks(), kStep * std::int64_t(i + 1));
        EXPECT_EQ(game.draws[i].TotalGameTime.Ticks(), kStep * std::int64_t(i + 1));
        EXPECT_FALSE(game.draws[i].IsRunningSlowly);
    }
    EXPECT_EQ(game.FrameCount(), 4);
    // The device came from the manager; Draw's clear reached the back buffer.
    const PresentationParameters& p = game.GraphicsDevice->PresentationParameters();
    EXPECT_EQ(p.BackBufferWidth, 32);
    EXPECT_EQ(p.BackBufferHeight, 16);
    const std::vector<Color> pixels = game.GraphicsDevice->GetBackBufferData();
    ASSERT_EQ(pixels.size(), 32u * 16u);
    EXPECT_TRUE(pixels[0] == Color::CornflowerBlue);
    EXPECT_TRUE(pixels.back() == Color::CornflowerBlue);
}

TEST(Game, ExitInUpdateEndsRun) {
    RecordingGame game;
    game.graphics.PreferredBackBufferWidth = game.graphics.PreferredBackBufferHeight = 8;
    game.exitAfterUpdates = 3;
    game.FrameLimit = 100;
    game.Run();
    EXPECT_EQ(game.updates.size(), 3u);
    EXPECT_EQ(game.draws.size(), 3u);  // the exiting frame still draws, as XNA
    EXPECT_TRUE(game.ExitRequested());
    EXPECT_EQ(game.calls.back(), "UnloadContent");
}

TEST(Game, FrameLimitFromEnvironment) {
    ::setenv("FXPORT_FRAMES", "2", 1);
    RecordingGame game;
    game.graphics.PreferredBackBufferWidth = game.graphics.PreferredBackBufferHeight = 8;
    game.Run();
    ::unsetenv("FXPORT_FRAMES");
    EXPECT_EQ(game.draws.size(), 2u);

    ::setenv("FXPORT_FRAMES", "two", 1);
    RecordingGame bad;
    bad.graphics.PreferredBackBufferWidth = bad.graphics.PreferredBackBufferHeight = 8;
    try {
        bad.Run();
        ADD_FAILURE() << "FXPORT_FRAMES=two was accepted";
    } catch (const ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("FXPORT_FRAMES='two'"), std::string::npos) << e.what();
    }
    ::unsetenv("FXPORT_FRAMES");
}

TEST(Game, FixedStepWaitsForAWholeStepAndCatchesUpWithSeveralUpdates) {
    RecordingGame game;
    game.graphics.PreferredBackBufferWidth = game.graphics.PreferredBackBufferHeight = 8;
    game.Start();
    const TimeSpan step = game.TargetElapsedTime;
    game.Tick(TimeSpan(step.Ticks() / 2));  // half a step: nothing due
    EXPECT_EQ(game.updates.size(), 0u);
    EXPECT_EQ(game.draws.size(), 0u);
    game.Tick(TimeSpan(step.Ticks() - step.Ticks() / 2));  // the rest of it: one Update, one Draw
    EXPECT_EQ(game.updates.size(), 1u);
    ASSERT_EQ(game.draws.size(), 1u);
    game.Tick(TimeSpan(step.Ticks() * 3 + 5));  // 3 steps and a bit: three Updates, one Draw
    ASSERT_EQ(game.updates.size(), 4u);
    ASSERT_EQ(game.draws.size(), 2u);
    for (std::size_t i = 1; i < 4; ++i) EXPECT_EQ(game.updates[i].ElapsedGameTime, step);
    EXPECT_EQ(game.draws[1].ElapsedGameTime, step * 3);  // Draw sees the steps it follows
    EXPECT_EQ(game.draws[1].TotalGameTime, step * 4);
    // The 5 leftover ticks carry over: one step less 5 more completes the next.
    game.Tick(TimeSpan(step.Ticks() - 5));
    EXPECT_EQ(game.updates.size(), 5u);
    EXPECT_EQ(game.draws.size(), 3u);
}

TEST(Game, IsRunningSlowlyAfterFiveFramesOfLagAndClearedWhenCaughtUp) {
    RecordingGame game;
    game.graphics.PreferredBackBufferWidth = game.graphics.PreferredBackBufferHeight = 8;
    game.Start();
    const TimeSpan step = game.TargetElapsedTime;
    // Two steps per tick: one frame of lag each. Slow from the tick where the lag reaches 5.
    for (int tick = 1; tick <= 6; ++tick) {
        game.Tick(step * 2);
        EXPECT_EQ(game.draws.back().IsRunningSlowly, tick >= 5) << "tick " << tick;
    }
    // Lag is 6; a single-step tick pays one back after its check, so the flag clears on the
    // seventh, the first tick that starts with no lag.
    for (int tick = 1; tick <= 7; ++tick) {
        game.Tick(step);
        EXPECT_EQ(game.draws.back().IsRunningSlowly, tick < 7) << "catch-up tick " << tick;
    }
}

TEST(Game, OneTickCountsAtMostHalfASecond) {
    RecordingGame game;
    game.graphics.PreferredBackBufferWidth = game.graphics.PreferredBackBufferHeight = 8;
    game.Start();
    game.Tick(TimeSpan::FromSeconds(10));
    const std::int64_t halfSecond = TimeSpan::TicksPerSecond / 2;
    EXPECT_EQ(std::int64_t(game.updates.size()), halfSecond / kStep);  // 29 steps of 16.6667 ms
    EXPECT_EQ(game.draws.size(), 1u);
}

TEST(Game, VariableStepUpdatesOncePerTickWithTheRealElapsedTime) {
    RecordingGame game;
    game.graphics.PreferredBackBufferWidth = game.graphics.PreferredBackBufferHeight = 8;
    game.IsFixedTimeStep = false;
    game.Start();
    game.Tick(TimeSpan::FromMilliseconds(5));
    game.Tick(TimeSpan::FromMilliseconds(40));
    ASSERT_EQ(game.updates.size(), 2u);
    ASSERT_EQ(game.draws.size(), 2u);
    EXPECT_EQ(game.updates[0].ElapsedGameTime, TimeSpan::FromMilliseconds(5));
    EXPECT_EQ(game.updates[1].ElapsedGameTime, TimeSpan::FromMilliseconds(40));
    EXPECT_EQ(game.draws[1].TotalGameTime, TimeSpan::FromMilliseconds(45));
}

TEST(Game, RealClockFixedStepWaitsForTheStep) {
    RecordingGame game;
    game.graphics.PreferredBackBufferWidth = game.graphics.PreferredBackBufferHeight = 8;
    game.Clock = GameClock::RealTime;
    game.TargetElapsedTime = TimeSpan::FromMilliseconds(20);
    game.Start();
    const auto start = std::chrono::steady_clock::now();
    game.Tick();  // the first tick finds one step's time
    game.Tick();  // the second must wait ~20 ms
    game.Tick();
    const double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    EXPECT_GE(ms, 39.0);
    EXPECT_GE(game.updates.size(), 3u);
    for (const GameTime& t : game.updates) EXPECT_EQ(t.ElapsedGameTime, TimeSpan::FromMilliseconds(20));
}

TEST(Game, TickBeforeStartIsAnError) {
    RecordingGame game;
    EXPECT_THROW(game.Tick(), InvalidOperation);
}

// A game that makes its own manager, as XNA games do in their constructor.
class OwnManagerGame : public Game {
public:
    GraphicsDeviceManager graphics{this};
    OwnManagerGame() {
        graphics.PreferredBackBufferWidth = 24;
        graphics.PreferredBackBufferHeight = 12;
    }
};

TEST(GraphicsDeviceManager, AGamesOwnManagerIsTheOneUsedAndApplyChangesResizes) {
    OwnManagerGame game;
    EXPECT_EQ(&game.graphicsDeviceManager(), &game.graphics);
    EXPECT_EQ(game.graphics.GraphicsDevice(), nullptr);
    game.Start();
    ASSERT_EQ(game.graphics.GraphicsDevice(), game.GraphicsDevice);
    EXPECT_EQ(game.GraphicsDevice->PresentationParameters().BackBufferWidth, 24);
    EXPECT_EQ(game.GraphicsDevice->PresentationParameters().BackBufferHeight, 12);

    game.graphics.PreferredBackBufferWidth = 40;
    game.graphics.PreferredBackBufferHeight = 30;
    game.graphics.ApplyChanges();
    EXPECT_EQ(game.GraphicsDevice->PresentationParameters().BackBufferWidth, 40);
    EXPECT_EQ(game.GraphicsDevice->Viewport.Width, 40);
    EXPECT_EQ(game.GraphicsDevice->Viewport.Height, 30);
    game.GraphicsDevice->Clear(Color::Red);
    const std::vector<Color> pixels = game.GraphicsDevice->GetBackBufferData();
    ASSERT_EQ(pixels.size(), 40u * 30u);
    EXPECT_TRUE(pixels[40 * 30 - 1] == Color::Red);
}

TEST(TimeSpan, TicksAndSeconds) {
    EXPECT_EQ(TimeSpan::FromSeconds(1.5).Ticks(), 15'000'000);
    EXPECT_EQ(TimeSpan::FromMilliseconds(16.6667).Ticks(), kStep);
    EXPECT_DOUBLE_EQ(TimeSpan(kStep).TotalSeconds(), 0.0166667);
    EXPECT_EQ(TimeSpan(1, 2, 3).Ticks(), (3600 + 120 + 3) * TimeSpan::TicksPerSecond);
    EXPECT_EQ(TimeSpan(0, 0, 0, 61, 250).Seconds(), 1);
    EXPECT_EQ(TimeSpan(0, 0, 0, 61, 250).Milliseconds(), 250);
    EXPECT_LT(TimeSpan::Zero, TimeSpan(1));
}

}  // namespace
}  // namespace fxport
