// A floating-point value handed to an Interlocked* intrinsic. fxc converts it to an integer the
// way D3D's ftoi/ftou do, saturating (NaN -> 0, out of range -> the nearest end): to int for
// InterlockedMax/Min, whose value then takes the destination's type, and to uint for the others
// (Add, And, Or, Xor, Exchange, CompareExchange, CompareStore: value and comparand), whatever
// the destination's type (vkd3d's uav-atomics pins each: 2147483648.0 maxes a uint and an int to
// 0x7fffffff; -1.0 adds 0 to an int and ands it to 0). glslang converts to the destination's type
// instead, with GLSL's conversion, undefined out of range. Each such operand is wrapped in
// fxport_ftoi / fxport_ftou, declared before the first function that needs them.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> interlockedValueConversions(const EffectSyntax& syntax);

}  // namespace fxport::xlate
