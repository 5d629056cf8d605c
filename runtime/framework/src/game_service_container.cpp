// GameServiceContainer: the registry behind the templates, and its errors naming the type.
#include "fxport/framework/game_service_container.h"

#include <cstdlib>
#include <string>

#if __has_include(<cxxabi.h>)
#include <cxxabi.h>
#endif

#include "fxport/graphics/errors.h"

namespace fxport {

namespace {

// "fxport::SpriteBatch" rather than the mangled "N6fxport11SpriteBatchE" in error messages.
std::string typeName(const std::type_info& type) {
#if __has_include(<cxxabi.h>)
    int status = 0;
    char* readable = abi::__cxa_demangle(type.name(), nullptr, nullptr, &status);
    if (status == 0 && readable) {
        std::string name(readable);
        std::free(readable);
        return name;
    }
#endif
    return type.name();
}

}  // namespace

void GameServiceContainer::add(const std::type_info& type, std::shared_ptr<void> provider) {
    if (!provider) throw ArgumentError("GameServiceContainer.AddService: the " + typeName(type) + " given is null");
    if (!services_.emplace(std::type_index(type), std::move(provider)).second)
        throw ArgumentError("GameServiceContainer.AddService: a service of type " + typeName(type) +
                            " is already present (RemoveService it first)");
}

void* GameServiceContainer::find(const std::type_info& type) const {
    auto it = services_.find(std::type_index(type));
    return it == services_.end() ? nullptr : it->second.get();
}

}  // namespace fxport
