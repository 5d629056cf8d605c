// Everything of fxport's XNA framework layer (Game with its components, services and window,
// GraphicsDeviceManager, GameTime, ContentManager) and the runtime it stands on:
// `#include "fxport/framework.h"` is a port's one include.
//
// Where C# cannot be mirrored (docs/API.md): a property is a public member when the object only stores
// it, a const method when it is computed or fixed at creation (texture->Width()), a getter plus
// setName(value) when setting does work; a name lookup that XNA answers with null throws ArgumentError
// naming the key (find(name) returns nullptr for the C# null test); Nullable<T> is std::optional<T>.
#pragma once

#include "fxport/framework/content_manager.h"
#include "fxport/framework/drawable_game_component.h"
#include "fxport/framework/game.h"
#include "fxport/framework/game_component.h"
#include "fxport/framework/game_component_collection.h"
#include "fxport/framework/game_service_container.h"
#include "fxport/framework/game_time.h"
#include "fxport/framework/game_window.h"
#include "fxport/framework/graphics_device_manager.h"
#include "fxport/framework/graphics_profile.h"
#include "fxport/framework/input.h"
#include "fxport/framework/time_span.h"
#include "fxport/graphics.h"
