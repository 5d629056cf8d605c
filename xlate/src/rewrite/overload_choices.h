// Calls of an overloaded function of the effect where fxc's choice is not glslang's. glslang's
// HLSL front end reads half and min16float as float, min16int as int and min16uint as uint, so
// `f(min16int)` beside `f(int)` is one function defined twice ("already has a body"), and it
// ranks double, widening and narrowing as GLSL does. fxc keeps each type apart and ranks an
// overload by the worst conversion any of its arguments needs, worst first (vkd3d's
// function-overload pins each step; fxc picks, glslang picked the other or gave up):
//   count narrowing (float4 -> float2)      worse than
//   class change (int <-> float, bool)       worse than
//   type narrowing (float -> half/min16float, int -> min16int; by any amount)  worse than
//   sign change (int <-> uint)               worse than
//   promotion (half -> float -> double, min16int -> int)  worse than
//   count widening (float -> float2)         worse than none.
// Overloads compare by these steps in order: the one that needs a step the other does not loses.
// Where a set of overloads takes half, double or a minimum-precision type, each definition is
// renamed (`f` -> `f_fxport_o1`) and each call names the overload fxc picks. Only where the name
// is called, and every use of it is a definition or a call whose arguments' types are evident
// and that has one winner; otherwise the set is left to glslang (and a tie to the checks,
// overload_ties.cpp). A set nothing calls or names otherwise keeps its names, except a definition
// a later one repeats as glslang reads them (`f(float)`, `f(min16float)`): that one is renamed.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> fxcOverloadChoices(const EffectSyntax& syntax);

}  // namespace fxport::xlate
