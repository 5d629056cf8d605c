// Game.Components: XNA's order of Initialize / LoadContent / Update / Draw / UnloadContent calls for
// the game and its GameComponents and DrawableGameComponents, UpdateOrder / DrawOrder with
// Enabled / Visible, and the collection itself. The expected logs are XNA 4's order (Game.Initialize
// initializes the components added so far then calls LoadContent; components added after it returns
// are initialized when added; those added in between never are), written out by hand. Headless.
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "fxport/framework.h"

namespace fxport {
namespace {

using Log = std::vector<std::string>;

// A GameComponent writing "<name>.<call>" to the log.
class LoggingComponent : public GameComponent {
public:
    LoggingComponent(fxport::Game* game, Log& log, std::string name) : GameComponent(game), log_(log), name_(std::move(name)) {}
    void Initialize() override { log_.push_back(name_ + ".Initialize"); }
    void Update(const GameTime&) override { log_.push_back(name_ + ".Update"); }

private:
    Log& log_;
    std::string name_;
};

class LoggingDrawable : public DrawableGameComponent {
public:
    LoggingDrawable(fxport::Game* game, Log& log, std::string name)
        : DrawableGameComponent(game), log_(log), name_(std::move(name)) {}
    void Initialize() override {
        log_.push_back(name_ + ".Initialize");
        DrawableGameComponent::Initialize();
    }
    void Update(const GameTime&) override { log_.push_back(name_ + ".Update"); }
    void Draw(const GameTime&) override {
        log_.push_back(name_ + ".Draw");
        EXPECT_NE(GraphicsDevice(), nullptr);
    }

protected:
    void LoadContent() override { log_.push_back(name_ + ".LoadContent"); }
    void UnloadContent() override { log_.push_back(name_ + ".UnloadContent"); }

private:
    Log& log_;
    std::string name_;
};

// Adds components at each point where XNA's rules differ, and logs its own calls.
class ComponentGame : public Game {
public:
    Log log;
    ComponentGame() {
        graphics.PreferredBackBufferWidth = graphics.PreferredBackBufferHeight = 8;
        Components.Add(new LoggingComponent(this, log, "A"));                  // before Run
        Components.Add(std::make_shared<LoggingDrawable>(this, log, "B"));
    }

protected:
    void Initialize() override {
        log.push_back("Game.Initialize");
        Components.Add(new LoggingComponent(this, log, "C"));  // before base.Initialize: initialized there
        Game::Initialize();
        Components.Add(new LoggingComponent(this, log, "D"));  // after it, still inside Initialize: never
    }
    void LoadContent() override {
        log.push_back("Game.LoadContent");
        auto e = std::make_shared<LoggingDrawable>(this, log, "E");  // in LoadContent: never initialized
        e->DrawOrder = -1;
        Components.Add(e);
    }
    void Update(const GameTime& gameTime) override {
        log.push_back("Game.Update");
        if (UpdateCount() == 1) Components.Add(new LoggingComponent(this, log, "F"));  // initialized now
        Game::Update(gameTime);
    }
    void Draw(const GameTime& gameTime) override {
        log.push_back("Game.Draw");
        Game::Draw(gameTime);
    }
    void UnloadContent() override { log.push_back("Game.UnloadContent"); }
};

TEST(GameComponents, CallsComeInXnasOrder) {
    ComponentGame game;
    game.FrameLimit = 1;
    game.Run();
    const Log expected = {
        "Game.Initialize", "A.Initialize", "B.Initialize", "B.LoadContent", "C.Initialize", "Game.LoadContent",
        // E was added in LoadContent, inside Game::Initialize, before D.
        "Game.Update", "F.Initialize", "A.Update", "B.Update", "C.Update", "E.Update", "D.Update", "F.Update",
        "Game.Draw", "E.Draw", "B.Draw",  // E: DrawOrder -1
        "B.UnloadContent", "E.UnloadContent", "Game.UnloadContent",
    };
    EXPECT_EQ(game.log, expected);
    EXPECT_EQ(game.Components.Count(), 6);
}

// Components whose Update / Draw log only their name, to read the order from.
class Ordered : public DrawableGameComponent {
public:
    Ordered(fxport::Game* game, Log& log, std::string name, int updateOrder, int drawOrder)
        : DrawableGameComponent(game), log_(log), name_(std::move(name)) {
        UpdateOrder = updateOrder;
        DrawOrder = drawOrder;
    }
    void Update(const GameTime&) override { log_.push_back("U" + name_); }
    void Draw(const GameTime&) override { log_.push_back("D" + name_); }

private:
    Log& log_;
    std::string name_;
};

class OrderGame : public Game {
public:
    Log log;
    OrderGame() { graphics.PreferredBackBufferWidth = graphics.PreferredBackBufferHeight = 8; }
};

TEST(GameComponents, UpdateAndDrawFollowTheirOrdersStablyAndSkipDisabledAndHidden) {
    OrderGame game;
    auto add = [&](const char* name, int updateOrder, int drawOrder) {
        auto c = std::make_shared<Ordered>(&game, game.log, name, updateOrder, drawOrder);
        game.Components.Add(c);
        return c;
    };
    add("a", 2, 0);
    add("b", 1, 5);
    auto c = add("c", 1, -3);  // equal UpdateOrder to b: after it (added later)
    add("d", 0, 5);            // equal DrawOrder to b: after it
    auto e = add("e", -1, 1);
    e->Enabled = false;        // drawn, not updated
    c->Visible = false;        // updated, not drawn
    game.RunOneFrame();
    EXPECT_EQ(game.log, (Log{"Ud", "Ub", "Uc", "Ua", "Da", "De", "Db", "Dd"}));

    // Orders and switches are read at every frame.
    game.log.clear();
    e->Enabled = true;
    e->UpdateOrder = 10;
    c->Visible = true;
    game.RunOneFrame();
    EXPECT_EQ(game.log, (Log{"Ud", "Ub", "Uc", "Ua", "Ue", "Dc", "Da", "De", "Db", "Dd"}));
}

// A component that removes itself and adds another while the game updates the collection.
class SelfRemoving : public GameComponent {
public:
    SelfRemoving(fxport::Game* game, Log& log) : GameComponent(game), log_(log) {}
    void Update(const GameTime&) override {
        log_.push_back("removing");
        Game()->Components.Add(std::make_shared<LoggingComponent>(Game(), log_, "N"));
        EXPECT_TRUE(Game()->Components.Remove(this));
        log_.push_back("removed");  // still alive: the update walks a copy that holds it
    }

private:
    Log& log_;
};

TEST(GameComponents, AComponentMayChangeTheCollectionWhileItUpdates) {
    OrderGame game;
    std::weak_ptr<GameComponent> watched;
    {
        auto remover = std::make_shared<SelfRemoving>(&game, game.log);
        watched = remover;
        game.Components.Add(remover);
    }
    game.RunOneFrame();  // N is added during the walk: initialized, updated from the next frame
    EXPECT_TRUE(watched.expired());
    game.RunOneFrame();
    EXPECT_EQ(game.log, (Log{"removing", "N.Initialize", "removed", "N.Update"}));
    EXPECT_EQ(game.Components.Count(), 1);
}

TEST(GameComponents, CollectionAddsRemovesAndRefusesDuplicates) {
    OrderGame game;
    Log log;
    auto* a = new LoggingComponent(&game, log, "a");
    auto b = std::make_shared<LoggingDrawable>(&game, log, "b");
    game.Components.Add(a);
    game.Components.Add(b);
    EXPECT_EQ(game.Components.Count(), 2);
    EXPECT_EQ(game.Components[0], a);
    EXPECT_EQ(game.Components[1], b.get());
    EXPECT_THROW((void)game.Components[2], ArgumentError);
    std::vector<GameComponent*> seen;
    for (const auto& component : game.Components) seen.push_back(component.get());
    EXPECT_EQ(seen, (std::vector<GameComponent*>{a, b.get()}));
    // XNA's ArgumentException for the same component twice (and the raw pointer stays owned once).
    EXPECT_THROW(game.Components.Add(a), std::invalid_argument);
    EXPECT_THROW(game.Components.Add(b), std::invalid_argument);
    EXPECT_THROW(game.Components.Add(static_cast<GameComponent*>(nullptr)), std::invalid_argument);
    EXPECT_TRUE(game.Components.Contains(a));
    EXPECT_TRUE(game.Components.Remove(b));
    EXPECT_FALSE(game.Components.Remove(b));
    EXPECT_EQ(game.Components.Count(), 1);
    // A removed component is no longer initialized or updated.
    game.RunOneFrame();
    EXPECT_EQ(log, (Log{"a.Initialize", "a.Update"}));
    // Its defaults are XNA's.
    EXPECT_TRUE(a->Enabled);
    EXPECT_EQ(a->UpdateOrder, 0);
    EXPECT_TRUE(b->Visible);
    EXPECT_EQ(b->DrawOrder, 0);
    EXPECT_EQ(a->Game(), &game);
}

}  // namespace
}  // namespace fxport
