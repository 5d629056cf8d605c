// Everything of fxport's XNA framework layer (Game, GraphicsDeviceManager, GameTime, ContentManager)
// and the runtime it stands on: `#include "fxport/framework.h"` is a port's one include.
#pragma once

#include "fxport/framework/content_manager.h"
#include "fxport/framework/game.h"
#include "fxport/framework/game_time.h"
#include "fxport/framework/graphics_device_manager.h"
#include "fxport/framework/time_span.h"
#include "fxport/graphics.h"
