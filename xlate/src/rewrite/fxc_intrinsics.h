// Intrinsics whose D3D meaning glslang computes differently, as fxc computes them:
//  - asin, acos, atan and atan2: D3D bytecode (SM2-SM5) has no inverse trigonometric instructions;
//    fxc expands each call into a fixed polynomial approximation, so a D3D shader's asin(0) is
//    6.75e-5, not 0, and effects (and the vkd3d conformance suite) depend on those values;
//  - lit(n_dot_l, n_dot_h, m): the specular term is pow(n_dot_h, m) (glslang 12 multiplies
//    n_dot_h * m), 0 where n_dot_l or n_dot_h is negative.
// Calls of the intrinsics are renamed to helper functions with fxc's expansion,
// inserted before the first function (on its line, so line numbers hold). An effect that defines
// a function of the same name, or calls one at file scope before any function, keeps its calls.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> intrinsicsAsFxc(const EffectSyntax& syntax);

}  // namespace fxport::xlate
