// `[unroll(n)]` as fxc reads it: n is the most iterations the loop runs, not a hint. fxc emits n
// copies of the body (each behind the loop's condition) and nothing after them, so
// `[unroll(4)] for (i = 0; i < 8; ++i);` leaves i == 4 (vkd3d's unroll L25; DXC kept the rule,
// hlsl-specs proposal 0022). glslang only marks the loop for unrolling and runs it to its end. A
// counter of our own joins the condition of such a `for` or `while`:
// `uint fxport_unroll7 = 0; [unroll(4)] for (i = 0; fxport_unroll7++ < (4) && (i < 8); ++i);`
// (the limit is checked first, so the condition runs n times, as in fxc's copies). The counter is
// declared in front of the statement, or both go in a new block where the loop is the unbraced
// body of an `if`/`else`/loop.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> unrollLimitsAsConditions(const EffectSyntax& syntax);

}  // namespace fxport::xlate
