// HLSL that fxc rejects and glslang accepts, found on the parsed effect and reported at file:line
// with fxc's wording and error number, so that an effect fxport compiles is one fxc compiles. Each
// rule is one function in fxc_rejections.cpp, with the vkd3d conformance file that pins it:
//  - a case of a switch that falls through into the next label, or an empty last case (X3533);
//  - `continue` in a case of a switch (switch);
//  - the same attribute twice on a statement, or [branch] with [flatten], [loop] with [unroll],
//    [fastopt] with [unroll] (X3524 / X3525);
//  - a modifier given twice, or modifiers that exclude each other (static uniform, out uniform,
//    out const, row_major column_major, nointerpolation centroid), and row_major/column_major on a type that is no matrix
//    (X3048 / X3049 / X3025);
//  - an assignment to a swizzle that names a component twice (`v.xx = ...`, X3018);
//  - a local `const` without an initial value (X3012);
//  - packoffset: outside a cbuffer member (a function's parameter, a $Globals variable, a struct member), not `cN` or `cN.x`, a vector crossing a register,
//    a matrix, array or struct not at `.x`, on some members of a cbuffer but not all (X3591 ...);
//  - a variable named like a built-in type (`float4 float;`, X3000);
//  - more than 14 constant buffers with $Globals and $Params (D3D's slots).
// Where fxc's rule is wider than a token pattern can judge, the pattern only flags what is
// certainly invalid; what it cannot judge is left to glslang.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"
#include "fx/source_map.h"

namespace fxport::xlate {

std::vector<Diagnostic> findFxcRejections(const EffectSyntax& syntax, const SourceMap& map);

}  // namespace fxport::xlate
