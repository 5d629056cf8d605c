// A matrix among several arguments of a constructor (`float4x4(1, 2, 3, 4, ..., a, 15, 16)` with a
// float2x2 a), as fxc reads it: its components row by row, a's first row then its second
// (vkd3d's matrix-indexing pins it). glslang 12 takes some of them column by column, or drops
// them: `float2x3(a, 1, 2)` came out with zeros. Such an argument is spelled as its rows,
// `a[0], a[1]`, which glslang reads in order. Only where the argument is a variable, a member or
// an element with constant indices (so naming it twice evaluates nothing twice) and its type is
// evidently a matrix of two rows and columns or more (expression_types.h).
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> matrixConstructorArgumentsAsRows(const EffectSyntax& syntax);

}  // namespace fxport::xlate
