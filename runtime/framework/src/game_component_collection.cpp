// GameComponentCollection: adding and removing, and XNA's initialize / update / draw / unload order
// (the rules are in game_component_collection.h).
#include "fxport/framework/game_component_collection.h"

#include <algorithm>
#include <string>

#include "fxport/framework/drawable_game_component.h"
#include "fxport/graphics/errors.h"

namespace fxport {

namespace {

// The components to run this time, by `order`, equal orders in the order of adding: a copy, so
// that what runs may change the collection (and a removed component lives until its call returns).
template <class Component, class Order>
std::vector<std::shared_ptr<Component>> byOrder(const std::vector<std::shared_ptr<GameComponent>>& items, Order order) {
    std::vector<std::shared_ptr<Component>> list;
    for (const auto& item : items)
        if (auto component = std::dynamic_pointer_cast<Component>(item)) list.push_back(std::move(component));
    std::stable_sort(list.begin(), list.end(), [&](const auto& a, const auto& b) { return order(*a) < order(*b); });
    return list;
}

}  // namespace

void GameComponentCollection::Add(Item component) {
    if (!component) throw ArgumentError("GameComponentCollection.Add: the component is null");
    if (Contains(component.get()))
        throw ArgumentError("GameComponentCollection.Add: the component is already in the collection");
    GameComponent* added = component.get();
    items_.push_back(std::move(component));
    if (initializeOnAdd_) added->Initialize();
    else notYetInitialized_.push_back(added);
}

void GameComponentCollection::Add(GameComponent* newComponent) {
    // Checked before a shared_ptr takes it: a second owner of a component already here would delete it.
    if (newComponent && Contains(newComponent))
        throw ArgumentError("GameComponentCollection.Add: the component is already in the collection");
    Add(Item(newComponent));
}

bool GameComponentCollection::Remove(const GameComponent* component) {
    auto it = std::find_if(items_.begin(), items_.end(), [&](const Item& item) { return item.get() == component; });
    if (it == items_.end()) return false;
    std::erase(notYetInitialized_, component);
    items_.erase(it);
    return true;
}

bool GameComponentCollection::Contains(const GameComponent* component) const {
    return std::any_of(items_.begin(), items_.end(), [&](const Item& item) { return item.get() == component; });
}

GameComponent* GameComponentCollection::operator[](int index) const {
    if (index < 0 || index >= Count())
        throw ArgumentError("GameComponentCollection[" + std::to_string(index) + "]: the collection holds " +
                            std::to_string(Count()) + " components");
    return items_[std::size_t(index)].get();
}

void GameComponentCollection::initializeAdded() {
    // A component's Initialize may add components: those are initialized in this loop too.
    while (!notYetInitialized_.empty()) {
        GameComponent* component = notYetInitialized_.front();
        notYetInitialized_.erase(notYetInitialized_.begin());
        // Held while it runs: its Initialize may remove it from the collection.
        auto held = std::find_if(items_.begin(), items_.end(), [&](const Item& item) { return item.get() == component; });
        if (held == items_.end()) continue;
        const Item keep = *held;
        keep->Initialize();
    }
}

void GameComponentCollection::update(const GameTime& gameTime) const {
    for (const auto& component : byOrder<GameComponent>(items_, [](const GameComponent& c) { return c.UpdateOrder; }))
        if (component->Enabled) component->Update(gameTime);
}

void GameComponentCollection::draw(const GameTime& gameTime) const {
    for (const auto& component :
         byOrder<DrawableGameComponent>(items_, [](const DrawableGameComponent& c) { return c.DrawOrder; }))
        if (component->Visible) component->Draw(gameTime);
}

void GameComponentCollection::unloadContent() const {
    const std::vector<Item> items = items_;
    for (const auto& item : items)
        if (auto* drawable = dynamic_cast<DrawableGameComponent*>(item.get())) drawable->UnloadContent();
}

}  // namespace fxport
