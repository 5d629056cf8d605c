// InterlockedCompareStore(dest, compare, value): glslang 12 emits nothing for it (the call is
// dropped, so the store never happens; vkd3d's uav-atomics pins the value). It is
// InterlockedCompareExchange without the original value, so it becomes that call with an extra
// out argument, a static uint the shader never reads (declared before the first function that
// calls it; glslang converts it for an int destination as it does the other operands).
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> compareStoreAsExchange(const EffectSyntax& syntax);

}  // namespace fxport::xlate
