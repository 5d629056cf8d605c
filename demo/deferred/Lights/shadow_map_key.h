// fxport addition (issue 16): ShadowMapKey, everything a light's shadow map is drawn from -- the
// light's matrices and DepthWriter values, the map (target and size), the DepthWriter effect and
// each caster's draws (model, absolute bone transforms, buffers and ranges) -- as bytes, so that
// LightManager redraws a map only when its key changed since the map was last drawn. Buffer
// contents are not in the key: a caster whose vertices are rewritten in place (SetData) must be
// re-added as a new buffer or the cache turned off (LightManager::reuseShadowMaps).
#pragma once

#include <cstring>
#include <type_traits>
#include <vector>

#include "deferred/xna.h"

namespace TheCansinDeferredRenderer::Lights {

class ShadowMapKey {
public:
    // Appends a value's bytes (floats compared bit for bit: the same inputs give the same key).
    template <class T>
    void add(const T& value) {
        static_assert(std::is_trivially_copyable_v<T>);
        const auto* p = reinterpret_cast<const unsigned char*>(&value);
        bytes_.insert(bytes_.end(), p, p + sizeof(T));
    }
    // Appends what LightManager::DrawModels draws from `models`.
    void addCasters(const std::vector<Model*>& models);

    bool operator==(const ShadowMapKey&) const = default;

private:
    std::vector<unsigned char> bytes_;
};

}  // namespace TheCansinDeferredRenderer::Lights
