// The index of a subscript is evaluated before its base when both call the effect's own
// functions: fxc (SM 2-5) computes `f()[g()]` by calling g, then f (vkd3d's side-effects L33: a
// function bumping a static counter returns 2.2 there, glslang's base-first order 1.3). Where the
// base is a call of an effect function returning a vector or matrix and the index calls one too,
// the subscript becomes a generated function taking the index first (HLSL evaluates arguments in
// order): `fxport_index_float4(g(), f())`. Only subscripts on one line whose index holds no
// subscript of its own.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> indexBeforeBaseForCalls(const EffectSyntax& syntax);

}  // namespace fxport::xlate
