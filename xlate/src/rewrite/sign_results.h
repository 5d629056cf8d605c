// HLSL's sign(x) is an int (intN for a vector) whatever x is: fxc computes (0 < x) - (x < 0) on
// integers, so `sign(d) / 2` is an integer division (0), `sign(d) & 1` and `sign(v) >> 1` are
// integer operations. glslang types sign like its argument (float), which made `sign(d) / 2` a
// float 0.5, `sign(d) & 1` a float `&` (GLSL the driver refuses) and `sign(v) >> 1` a shift of
// the float's bits. Each call on a scalar or vector whose type the tokens tell is cast to fxc's
// int type before glslang reads it; an effect's own sign() and matrices are left as they are.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> signResultsAsInts(const EffectSyntax& syntax);

}  // namespace fxport::xlate
