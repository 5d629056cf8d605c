// asin, acos, atan and atan2 as fxc computes them. D3D bytecode (SM2-SM5) has no inverse
// trigonometric instructions: fxc expands each call into a fixed polynomial approximation, so a
// D3D shader's asin(0) is 6.75e-5, not 0, and effects (and the vkd3d conformance suite) depend on
// those values. Calls of the intrinsics are renamed to helper functions with fxc's expansion,
// inserted before the first function (on its line, so line numbers hold). An effect that defines
// a function of the same name, or calls one at file scope before any function, keeps its calls.
#pragma once

#include <vector>

#include "fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> inverseTrigAsFxc(const EffectSyntax& syntax);

}  // namespace fxport::xlate
