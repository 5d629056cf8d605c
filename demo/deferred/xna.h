// The names the port of "Deferred Rendering in XNA 4" (seed 000) uses: the runtime's XNA types
// (fxport::Effect, Matrix, ...) and the demo scaffolding (Game, ContentManager), visible unqualified
// inside the tutorial's namespace so that the C++ reads like the C#.
#pragma once

#include "fxport/framework.h"
#include "common/pass_timer.h"
#include "fxport/graphics.h"
#include "fxport/graphics/model.h"
#include "fxport/graphics/sprite_batch.h"
#include "fxport/graphics/sprite_font.h"

namespace TheCansinDeferredRenderer {
using namespace fxport;
using namespace fxport::demo;
}  // namespace TheCansinDeferredRenderer
