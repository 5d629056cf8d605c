// GameComponentCollection: XNA's Game.Components, and the rules by which the game runs them.
//
// Ownership (C#'s components are garbage collected): the collection shares ownership of each
// component through std::shared_ptr. `Components.Add(new MyComponent(this))` -- the C# line as is --
// hands a new'd component over; `Components.Add(std::make_shared<MyComponent>(this))` lets the game
// keep a shared_ptr of its own. A component lives while it is in the collection or the game holds
// it; Remove lets it go. Never Add the address of an object the game owns otherwise (a member).
//
// XNA's order of calls (XNA 4's Game, FNA's and MonoGame's alike):
// - Game::Initialize initializes every component added until then (and those those add), then
//   calls LoadContent; a DrawableGameComponent's Initialize calls its own LoadContent.
// - Once Game::Initialize has returned, a component is initialized as it is added. One added in
//   between -- in LoadContent or after Game::Initialize() in an Initialize override -- is never
//   initialized, as in XNA (it is still updated and drawn).
// - Game::Update updates the Enabled components by UpdateOrder, Game::Draw draws the Visible
//   DrawableGameComponents by DrawOrder; equal orders keep the order of adding. Both walk a copy,
//   so a component may add or remove components (itself too) while it runs.
// - When Game::Run ends, each DrawableGameComponent's UnloadContent runs, in the order of the
//   collection (XNA's Game.Dispose; initialized or not), then the game's UnloadContent.
#pragma once

#include <memory>
#include <vector>

#include "fxport/framework/game_component.h"

namespace fxport {

class GameComponentCollection {
public:
    using Item = std::shared_ptr<GameComponent>;

    // Throws ArgumentError (XNA's ArgumentException) for null or a component already there.
    void Add(Item component);
    void Add(GameComponent* newComponent);
    // Collection<T>.Remove: false when `component` is not there.
    bool Remove(const GameComponent* component);
    bool Remove(const Item& component) { return Remove(component.get()); }
    bool Contains(const GameComponent* component) const;
    void Clear() { items_.clear(); }

    int Count() const { return int(items_.size()); }
    // Throws ArgumentError outside 0..Count()-1.
    GameComponent* operator[](int index) const;
    auto begin() const { return items_.begin(); }
    auto end() const { return items_.end(); }

private:
    friend class Game;
    void initializeAdded();
    void update(const GameTime& gameTime) const;
    void draw(const GameTime& gameTime) const;
    void unloadContent() const;

    std::vector<Item> items_;
    std::vector<GameComponent*> notYetInitialized_;
    bool initializeOnAdd_ = false;  // set once Game::Initialize has returned (XNA's inRun)
};

}  // namespace fxport
