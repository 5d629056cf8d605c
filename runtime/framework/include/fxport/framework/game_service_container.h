// GameServiceContainer: XNA's Game.Services, a registry of one object per type that components look
// up instead of reaching into the game. C#'s Type argument becomes the template argument:
//
//   Services.AddService(typeof(SpriteBatch), spriteBatch);   ->  Services.AddService<SpriteBatch>(spriteBatch);
//   Services.GetService(typeof(SpriteBatch)) as SpriteBatch  ->  Services.GetService<SpriteBatch>()
//   Services.RemoveService(typeof(SpriteBatch))              ->  Services.RemoveService<SpriteBatch>()
//
// The container does not own what a raw pointer or unique_ptr gives it (the game keeps its
// SpriteBatch in a unique_ptr or as a member, and must remove the service before destroying it); a
// std::shared_ptr given to it is kept alive until the service is removed or the game ends.
#pragma once

#include <map>
#include <memory>
#include <typeindex>
#include <typeinfo>

namespace fxport {

class GameServiceContainer {
public:
    // Registers `provider` as the service of type T. Throws ArgumentError (a std::invalid_argument,
    // as XNA's ArgumentException) when a T is already registered or `provider` is null.
    template <class T> void AddService(T* provider) { add(typeid(T), std::shared_ptr<void>(provider, [](void*) {})); }
    template <class T> void AddService(const std::unique_ptr<T>& provider) { AddService<T>(provider.get()); }
    template <class T> void AddService(std::shared_ptr<T> provider) {
        add(typeid(T), std::static_pointer_cast<void>(std::move(provider)));
    }
    // The service of type T; nullptr when none is registered (C#'s `as T` giving null).
    template <class T> T* GetService() const { return static_cast<T*>(find(typeid(T))); }
    // Forgets the service of type T; nothing happens when there is none (as XNA).
    template <class T> void RemoveService() { services_.erase(std::type_index(typeid(T))); }

private:
    void add(const std::type_info& type, std::shared_ptr<void> provider);
    void* find(const std::type_info& type) const;

    // The pointer stored is a T* (converted to void* from T*, so static_cast back to T* is exact).
    std::map<std::type_index, std::shared_ptr<void>> services_;
};

}  // namespace fxport
