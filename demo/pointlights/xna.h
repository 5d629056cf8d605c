// The names the port of Catalin Zima's deferred rendering series (seed 001, chapter "Point Lights")
// uses: the runtime's XNA types and the demo scaffolding, visible unqualified inside the
// tutorial's namespace so that the C++ reads like the C#.
#pragma once

#include "fxport/framework.h"
#include "common/pass_timer.h"
#include "fxport/graphics.h"
#include "fxport/graphics/model.h"

namespace DeferredLighting {
using namespace fxport;
using namespace fxport::demo;

}  // namespace DeferredLighting
