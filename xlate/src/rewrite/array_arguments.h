// An array passed to a parameter of the effect's own function that is an array of another shape
// with as many elements: fxc copies the elements in order (`float a[2][3]` takes a `float f[3][2]`
// or a `float g[6]`, row after row; vkd3d's array-parameters pins it); glslang finds no matching
// overload (FX2001). For each such call an overload taking the argument's shape is added after
// the function (on its last line, so line numbers hold): it copies the elements into an array of
// the parameter's shape and calls the function with it. Only `in` parameters of a function
// defined once, arguments that are variables whose declared element type is the parameter's.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> arrayArgumentOverloads(const EffectSyntax& syntax);

}  // namespace fxport::xlate
