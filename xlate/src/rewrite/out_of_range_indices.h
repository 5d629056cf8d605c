// A literal index past the end of an array (`arr[100]` of `float4 arr[4]`): before SM6 fxc refuses
// it only in code that runs, and compiles it in dead code (`bool x = false; if (x) { arr[100] = 0;
// }`, vkd3d's hard-copy-prop); glslang refuses it wherever it is ("array index out of range"). So
// the index is passed through `fxport_index(N)`, which glslang does not fold: legalisation drops
// the dead code, and spirv/constant_index_bounds.h refuses an index still past the end after it,
// as fxc does.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> outOfRangeIndicesDeferred(const EffectSyntax& syntax);

}  // namespace fxport::xlate
