// The Game members nearly every XNA Game1 touches besides the loop: Services, IsActive,
// IsMouseVisible, Window (ClientBounds, AllowUserResizing, Title), and GraphicsDeviceManager's
// IsFullScreen / ToggleFullScreen / SynchronizeWithVerticalRetrace / PreferMultiSampling /
// GraphicsProfile, with XNA's defaults. Headless (OSMesa): the window settings must be accepted
// and leave the back buffer and the frames as they were.
#include <algorithm>
#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "fxport/framework.h"

namespace fxport {
namespace {

struct Scoreboard {
    int score = 0;
};
struct Base {
    virtual ~Base() = default;
    int id = 1;
};
struct Derived : Base {};

class PlainGame : public Game {
public:
    PlainGame() { graphics.PreferredBackBufferWidth = graphics.PreferredBackBufferHeight = 8; }
};

TEST(GameServices, AddGetRemoveAndDuplicates) {
    PlainGame game;
    Scoreboard board;
    EXPECT_EQ(game.Services.GetService<Scoreboard>(), nullptr);  // C#'s `as T` giving null
    game.Services.AddService<Scoreboard>(&board);
    EXPECT_EQ(game.Services.GetService<Scoreboard>(), &board);
    // XNA's ArgumentException for a second service of one type, and for null.
    Scoreboard other;
    EXPECT_THROW(game.Services.AddService<Scoreboard>(&other), std::invalid_argument);
    EXPECT_EQ(game.Services.GetService<Scoreboard>(), &board);
    EXPECT_THROW(game.Services.AddService<Base>(static_cast<Base*>(nullptr)), std::invalid_argument);
    game.Services.RemoveService<Scoreboard>();
    EXPECT_EQ(game.Services.GetService<Scoreboard>(), nullptr);
    game.Services.RemoveService<Scoreboard>();  // absent: nothing happens, as XNA
    game.Services.AddService<Scoreboard>(&other);
    EXPECT_EQ(game.Services.GetService<Scoreboard>(), &other);
}

TEST(GameServices, KeyedByTheTypeNamedAndSharedPointersKeptAlive) {
    PlainGame game;
    auto derived = std::make_shared<Derived>();
    std::weak_ptr<Derived> watched = derived;
    game.Services.AddService<Base>(derived);  // registered as Base, as typeof(Base) in C#
    derived.reset();
    EXPECT_EQ(game.Services.GetService<Derived>(), nullptr);
    ASSERT_NE(game.Services.GetService<Base>(), nullptr);
    EXPECT_EQ(game.Services.GetService<Base>()->id, 1);
    EXPECT_FALSE(watched.expired());
    game.Services.RemoveService<Base>();
    EXPECT_TRUE(watched.expired());
    auto owned = std::make_unique<Scoreboard>();
    game.Services.AddService(owned);  // a unique_ptr the game keeps: type deduced, not owned
    EXPECT_EQ(game.Services.GetService<Scoreboard>(), owned.get());
}

TEST(GameServices, ADuplicateNamesTheType) {
    PlainGame game;
    Scoreboard board;
    game.Services.AddService(&board);
    try {
        game.Services.AddService(&board);
        FAIL() << "no exception";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("fxport::(anonymous namespace)::Scoreboard"), std::string::npos) << e.what();
    }
}

TEST(GameMembers, DefaultsAreXnas) {
    PlainGame game;
    EXPECT_FALSE(game.IsMouseVisible);
    EXPECT_FALSE(game.Window.AllowUserResizing);
    EXPECT_FALSE(game.graphics.IsFullScreen);
    EXPECT_TRUE(game.graphics.SynchronizeWithVerticalRetrace);
    EXPECT_FALSE(game.graphics.PreferMultiSampling);
    EXPECT_EQ(game.graphics.GraphicsProfile, GraphicsProfile::Reach);
    EXPECT_EQ(game.Components.Count(), 0);
    // Nothing to be active in or to measure before the game has started.
    EXPECT_FALSE(game.IsActive());
    EXPECT_EQ(game.Window.ClientBounds(), Rectangle::Empty);
}

// Flips every window setting in Update and clears in Draw: headless, each must leave the frames
// and the back buffer as they were.
class SettingsGame : public Game {
public:
    bool activeInEveryUpdate = true;
    SettingsGame() {
        graphics.PreferredBackBufferWidth = 24;
        graphics.PreferredBackBufferHeight = 10;
        graphics.IsFullScreen = true;  // before Run, as Game1's constructor does
        graphics.SynchronizeWithVerticalRetrace = false;
        graphics.GraphicsProfile = GraphicsProfile::HiDef;
        IsMouseVisible = true;
        Window.AllowUserResizing = true;
        Window.Title = "Settings";
    }

protected:
    void Update(const GameTime& gameTime) override {
        activeInEveryUpdate = activeInEveryUpdate && IsActive();
        IsMouseVisible = !IsMouseVisible;
        Window.AllowUserResizing = !Window.AllowUserResizing;
        Window.Title = "Frame " + std::to_string(UpdateCount());
        if (UpdateCount() == 2) graphics.ToggleFullScreen();
        if (UpdateCount() == 3) {
            graphics.SynchronizeWithVerticalRetrace = true;
            graphics.ApplyChanges();
        }
        Game::Update(gameTime);
    }
    void Draw(const GameTime&) override { GraphicsDevice->Clear(Color::CornflowerBlue); }
};

TEST(GameMembers, WindowSettingsAreHarmlessHeadless) {
    SettingsGame game;
    game.FrameLimit = 4;
    game.Run();
    EXPECT_EQ(game.FrameCount(), 4);
    EXPECT_TRUE(game.activeInEveryUpdate);  // headless: always active
    EXPECT_FALSE(game.graphics.IsFullScreen);  // toggled once, from true
    const PresentationParameters& p = game.GraphicsDevice->PresentationParameters();
    EXPECT_EQ(p.BackBufferWidth, 24);
    EXPECT_EQ(p.BackBufferHeight, 10);
    EXPECT_EQ(game.Window.ClientBounds(), Rectangle(0, 0, 24, 10));
    const std::vector<Color> pixels = game.GraphicsDevice->GetBackBufferData();
    EXPECT_TRUE(pixels.front() == Color::CornflowerBlue);
    EXPECT_TRUE(pixels.back() == Color::CornflowerBlue);
}

TEST(GameMembers, ToggleFullScreenBeforeTheGameStartsOnlyFlipsTheField) {
    PlainGame game;
    game.graphics.ToggleFullScreen();
    EXPECT_TRUE(game.graphics.IsFullScreen);
    EXPECT_EQ(game.GraphicsDevice, nullptr);
    game.graphics.ToggleFullScreen();
    EXPECT_FALSE(game.graphics.IsFullScreen);
}

TEST(GameMembers, ClientBoundsFollowTheBackBuffer) {
    PlainGame game;
    game.graphics.PreferredBackBufferWidth = 40;
    game.graphics.PreferredBackBufferHeight = 30;
    game.RunOneFrame();
    EXPECT_TRUE(game.IsActive());
    EXPECT_EQ(game.Window.ClientBounds(), Rectangle(0, 0, 40, 30));
    game.graphics.PreferredBackBufferWidth = 16;
    game.graphics.PreferredBackBufferHeight = 12;
    game.graphics.ApplyChanges();
    EXPECT_EQ(game.Window.ClientBounds(), Rectangle(0, 0, 16, 12));
}

std::size_t occurrences(const std::string& text, const std::string& word) {
    std::size_t n = 0;
    for (auto at = text.find(word); at != std::string::npos; at = text.find(word, at + 1)) ++n;
    return n;
}

TEST(GameMembers, PreferMultiSamplingWarnsOnceNamingTheMember) {
    PlainGame game;
    game.graphics.PreferMultiSampling = true;
    testing::internal::CaptureStderr();
    game.RunOneFrame();
    game.graphics.ApplyChanges();
    game.RunOneFrame();
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(occurrences(err, "GraphicsDeviceManager.PreferMultiSampling"), 1u) << err;
    EXPECT_EQ(game.FrameCount(), 2);
}

TEST(GameMembers, NoMultiSamplingNoWarning) {
    PlainGame game;
    testing::internal::CaptureStderr();
    game.RunOneFrame();
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_EQ(occurrences(err, "PreferMultiSampling"), 0u) << err;
}

// GraphicsAdapter.DefaultAdapter.CurrentDisplayMode, which games size their back buffer from:
// headless (no monitor) the documented 1920x1080; with a monitor its current mode, one of the
// modes it supports.
TEST(GameMembers, DefaultAdapterReportsADisplayMode) {
    GraphicsAdapter& adapter = GraphicsAdapter::DefaultAdapter();
    const DisplayMode mode = adapter.CurrentDisplayMode();
    const std::vector<DisplayMode> modes = adapter.SupportedDisplayModes();
    ASSERT_FALSE(modes.empty());
    if (adapter.IsHeadless()) {
        EXPECT_EQ(mode, (DisplayMode{1920, 1080, SurfaceFormat::Color, 60}));
        EXPECT_EQ(modes.size(), 1u);
    } else {
        EXPECT_GT(mode.Width, 0);
        EXPECT_NE(std::find(modes.begin(), modes.end(), mode), modes.end());
    }
    EXPECT_NEAR(mode.AspectRatio(), float(mode.Width) / float(mode.Height), 1e-6);
    EXPECT_EQ(mode.TitleSafeArea(), Rectangle(0, 0, mode.Width, mode.Height));
    EXPECT_EQ(GraphicsAdapter::Adapters().size(), 1u);
    EXPECT_TRUE(adapter.IsDefaultAdapter());
}

}  // namespace
}  // namespace fxport
