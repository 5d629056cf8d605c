// Out and inout arguments through conversions, as fxc takes them. glslang 12 converts an inout
// argument of another type on the way in but never writes it back (`void f(inout float4 a)` on an
// int4 x leaves x as it was), and takes an explicit cast on an out argument (`f((float4)x)`,
// `f((int4)p)`) as a value: the write is lost, or refused ("l-value required"). fxc writes back
// through the cast as if it stood on the left of an assignment (lvalue_casts.h): `(float2)p`
// writes p.xy, `(int4)p` of a float4 p writes p = (float4)(int4)value.
// Each such call goes through a wrapper of its own, inserted before the caller on the caller's
// first line, whose parameter has the target's type: it converts in (inout), calls, and writes
// back with fxc's rule. Only calls of a function with one overload of that arity, numeric
// non-matrix targets (`x`, `s.member`) and numeric casts are taken; the rest is left to glslang.
// The same wrapper reads an inout argument that is an element of a typed UAV (`f(u[id.xy])`,
// `RWTexture2D`/`RWBuffer`): glslang copies such an element out after the call but never in
// before it (the callee reads an undefined value), so the element is passed twice, once `in` (a
// load glslang does) and once `out` (the write back it does), when its index has no side effects.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> outArgumentsThroughConversions(const EffectSyntax& syntax);

}  // namespace fxport::xlate
