// Brace initializers written flat, as fxc takes them: `float2 o[2] = {1, 2, 3, 4};`,
// `float2x2 m = {1, 2, 3, 4};`, `S s = {1, 2, 3};` for `struct S { float a; float2 b; }`,
// BakingLab's `SH4 shr = { sh.c[0].x, sh.c[1].x, sh.c[2].x, sh.c[3].x };` for `struct SH4 { float
// c[4]; }`, `float c[4] = {p.xy, p.zw};`. fxc flattens the list into components and fills the
// declared type's components in order; glslang wants one initializer per array element and struct
// member, and refuses the flat form ("cannot convert parameter 3 from 'const int' to '2-component
// vector of float'", "wrong number of structure members"). The list of an array, struct or matrix
// is regrouped into the nested form when every item is a literal, a constructor of literals, a
// variable named alone or (in a function) an expression whose type expression_types.h knows; any
// other list is left to glslang, which judges it as written. A scalar or vector item whose
// components land together stays where it is written (`{float2(p.x, p.y), p.z}`), so other
// rewrites' edits inside it still apply; an item split across several places is spelled once per
// component (`(p.xy)[1]`), and where that would repeat a call or an assignment, it and every item
// before it that is not a literal are first evaluated, in order, into temporaries declared just
// before the declaration (`float2 fxport_init_N = f(q).xy;`), so each runs once as in fxc. A
// static's list, or one where no statement can go before it, is then left to glslang.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> regroupFlatInitializers(const EffectSyntax& syntax);

}  // namespace fxport::xlate
