// HLSL's ldexp(x, e) is x * 2^e for any float e: fxc compiles it as an exp (2^e) and a mul, so
// ldexp(3, 0.5) is 4.2426. glslang maps it onto GLSL's ldexp, whose exponent is an int, and
// truncates e first (ldexp(3, 0.5) became 3). Each call of the intrinsic is spelled out as fxc
// computes it, `((x) * exp2(e))`, before glslang reads it, where both arguments are scalars or
// vectors of one width; matrices and an effect's own ldexp() are left alone.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> ldexpAsExp2(const EffectSyntax& syntax);

}  // namespace fxport::xlate
