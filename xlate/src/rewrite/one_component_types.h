// float1, int1, half1 ... (one-component vectors) respelled as their scalars before glslang.
// fxc treats a one-component vector like a scalar in expressions: it broadcasts in `float1 + float2`
// and converts freely; glslang keeps it a vector of one, refuses `float1 + float2` ("Could not
// perform requested binary operation") and crashes on `mul(float1, matrix)`. A scalar has the
// same storage, register and varying; swizzles like `.x`/`.xxxx` work on scalars in both.
// `v[0]` of such a vector (a variable, a parenthesised expression or a call whose type is evident:
// expression_types.h) drops its index, as a scalar is its own component 0.
// One-component matrices (float1x1) and vector<T, 1> are left as written, and so are the parameter
// types of overloaded functions (fxc lets `f(float)` and `f(float1)` be two functions).
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> respellOneComponentVectors(const EffectSyntax& syntax);

}  // namespace fxport::xlate
