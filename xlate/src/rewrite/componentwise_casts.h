// Casts between arrays, structs, vectors and matrices of as many components or fewer, as fxc takes
// them: the source's components in order (struct members in order, array elements, matrix rows)
// fill the cast's type (`(int4) f` of a `float f[5]` is int4(f[0], f[1], f[2], f[3]);
// `a = (struct apple) f;` fills a's members from f's elements). glslang refuses them ("cannot
// convert parameter", "constructing non-array constituent from array argument", "wrong number of
// structure members"; vkd3d's cast-componentwise-compatible and -equal pin them). Rewritten:
//  - `(T) x` with T numeric and x an array or struct variable: T's constructor from x's first
//    components, each named (`x[0]`, `x.aa.y` ...);
//  - `y = (T) x;` with T a struct or an array (y declared as T): one assignment per component.
//  - `(T[N]...) s` with s a scalar literal or variable, in an initializer or `y = (T[N]) s;`: every
//    element (T)(s), as fxc fills it (`(float4[4])0`; glslang wants one argument per element).
// Only where x and y are variables whose types the source declares, and every component numeric;
// a source with fewer components than T is left to glslang, which refuses it as fxc does.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> componentwiseCasts(const EffectSyntax& syntax);

}  // namespace fxport::xlate
