// INTERNAL: the library's one way to a GraphicsDevice's or an Effect's private state. Both classes
// befriend ImplAccess; their public headers have no accessor, so a host cannot reach Impl.
#pragma once

#include "fxport/graphics/effect.h"
#include "fxport/graphics/graphics_device.h"

namespace fxport {

struct ImplAccess {
    static GraphicsDevice::Impl& of(GraphicsDevice& device) { return *device.impl_; }
    static const GraphicsDevice::Impl& of(const GraphicsDevice& device) { return *device.impl_; }
    static Effect::Impl& of(Effect& effect) { return *effect.impl_; }
};

inline GraphicsDevice::Impl& deviceImpl(GraphicsDevice& device) { return ImplAccess::of(device); }
inline const GraphicsDevice::Impl& deviceImpl(const GraphicsDevice& device) { return ImplAccess::of(device); }
inline Effect::Impl& effectImpl(Effect& effect) { return ImplAccess::of(effect); }

}  // namespace fxport
