// `t.GetDimensions(u1, f2)`: fxc takes any mix of uint and float out arguments (vkd3d's
// getdimensions pins it); glslang has one overload with all uint and one with all float, and calls
// a mix ambiguous. Such a call statement gets uint temporaries, assigned to the arguments after
// it: `{ uint fxport_dim0, fxport_dim1; t.GetDimensions(fxport_dim0, fxport_dim1); u1 = fxport_dim0;
// f2 = fxport_dim1; }`, on the statement's line (a mip-level argument, an input, is passed as is).
// The texture may be any receiver method_receivers.h reads (`T[0]`, a texture parameter, a struct's
// texture member) and the statement may follow `if (...)`, `else` or a case label. Calls whose out
// arguments share one type, and objects other than textures, stay.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> mixedDimensionOutputs(const EffectSyntax& syntax);

}  // namespace fxport::xlate
