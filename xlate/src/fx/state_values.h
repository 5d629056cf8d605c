// INTERNAL: the typed value of a state from a number in fxport's canonical enum order (what the
// state parser's tables produce); the public half (defaults, D3D9 codes) is in compiled_effect.h.
#pragma once

#include "fxport/xlate/compiled_effect.h"

namespace fxport::xlate {

// `number` is a bool (0/1), an int, a float, or the index of an enum value in its enum class.
StateValue stateValueFromCanonical(RenderState state, double number);

}  // namespace fxport::xlate
