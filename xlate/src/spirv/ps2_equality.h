// Float equality as fxc compiles it for ps_2_0, which has no compare instruction but cmp (x >= 0
// ? y : z): a == b becomes cmp(-(a - b)², 1, 0), so two numbers are equal when their difference
// squared is 0, which it also is when the difference is below about 1e-19 (the square underflows;
// vkd3d float-comparison L92: 1e-37 == 0 and 1e-37 == -1e-37 are true in ps_2_0, not in ps_3_0).
// Every 32-bit float ==/!= of a ps_2_0 module compares (a - b) * (a - b) with 0; before
// legalisation folds constants, and before the other SM 2 passes add comparisons of their own.
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

bool equalityBySquaredDifference(ParsedSpirv& m);

}  // namespace fxport::xlate
