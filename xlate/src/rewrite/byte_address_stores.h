// RWByteAddressBuffer.Store2/3/4(address, value) with a scalar value (MiniEngine's
// FXAAResolveWorkQueueCS `WorkCounts.Store2(0, 0);`): fxc converts the argument to the uintN
// parameter, a scalar by replicating it. glslang takes the scalar as it is and emits invalid SPIR-V
// (a literal) or crashes (a variable). So the value becomes `(uintN)(value)`: the conversion fxc
// makes for every argument (a vector is truncated or value-converted the same way).
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> byteAddressStoreValues(const EffectSyntax& syntax);

}  // namespace fxport::xlate
