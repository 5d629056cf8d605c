// Brace initializers written flat, as fxc takes them: `float2 o[2] = {1, 2, 3, 4};`,
// `float2x2 m = {1, 2, 3, 4};`, `S s = {1, 2, 3};` for `struct S { float a; float2 b; }`. fxc fills
// the declared type's components in order from the flattened list; glslang wants one initializer
// per array element and struct member, and refuses the flat form ("cannot convert parameter 3 from
// 'const int' to '2-component vector of float'", "wrong number of structure members"). Lists of
// literals (and constructors of literals) for an array, struct or matrix are regrouped into the
// nested form with the same literal texts; any other list is left to glslang.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> regroupFlatInitializers(const EffectSyntax& syntax);

}  // namespace fxport::xlate
