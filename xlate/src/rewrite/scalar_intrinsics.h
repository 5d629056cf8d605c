// Intrinsics that fxc takes on a scalar and glslang 12 refuses with "ambiguous best function under
// implicit type conversion" (its overloads take vectors or matrices, and a scalar promotes to each
// size): normalize(x) is x / |x| (fxc: x * rsqrt(x * x)), determinant(x) and transpose(x) are x,
// reflect(i, n) and refract(i, n, eta) their formulas on one component, noise(x) is noise at
// (x, 0) (vkd3d's normalize, determinant, transpose, reflect, refract and noise pin them). A call
// whose arguments are all evidently scalars (literals, variables declared float, int, float1 ...)
// calls a helper for that scalar instead, inserted before the first function; determinant of a local
// or parameter matrix of one row or one column (float2x1 m) is its first element, as fxc takes the determinant
// of a non-square matrix's top-left square. An effect with its own function of that name keeps
// its calls.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> scalarIntrinsicCalls(const EffectSyntax& syntax);

}  // namespace fxport::xlate
