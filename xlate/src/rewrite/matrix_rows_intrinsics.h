// all, any, asint, asuint, asfloat and sign of a matrix (float2x2 ...), as fxc computes them: on every
// component. glslang passes the matrix through and SPIRV-Cross writes GLSL no driver takes
// (`notEqual(mat2, float)`, `floatBitsToInt(mat2)`, `sign(mat2)`; vkd3d's all, any, asint, asuint and
// sign pin them).
// Such a call becomes a helper that works row by row: `fxport_all_float2x2(m)` is
// `all(m[0]) && all(m[1])`, `fxport_asint_float2x2(m)` is `int2x2(asint(m[0]), asint(m[1]))`; sign's matrix
// holds the same values as floats (glslang's int matrices become GLSL no driver takes).
// Only where the argument is evidently a matrix of two rows and columns or more (expression_types.h).
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> matrixIntrinsicsByRow(const EffectSyntax& syntax);

}  // namespace fxport::xlate
