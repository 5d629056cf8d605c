// Values of different shapes combined as fxc combines them, where glslang's HLSL front end finds
// no overload (FX2001) or refuses the operation:
//  - element-wise intrinsics (clamp, max, min, mad, lerp, smoothstep, pow, step, fmod, ldexp) with
//    a matrix argument convert every argument to one common type first: the smallest rows and
//    the smallest columns of the matrix arguments (a scalar fills that shape), the highest
//    component type (float for the float-only ones). `lerp(float3x2, float2x3, float3x4)` is a
//    float2x2 of each argument's top-left 2x2 (vkd3d's clamp, lerp, ldexp, max-min, pow,
//    smoothstep and step pin it). A call on full matrices becomes one call per row (glslang
//    crashes on lerp(float2x2 ...), and SPIRV-Cross writes clamp(mat2, ...) that no driver takes);
//  - a binary operator between matrices of different shapes computes in the smaller rows and
//    columns (`float1x4 + float4x4` adds the first row; vkd3d's shape pins it);
//  - mul with a one-component vector or matrix (glslang crashes), or with a one-row or one-column
//    matrix (a vector to glslang, which mul would take as a row or a column where fxc does not):
//    a helper with fxc's product, a vector a row on the left and a column on the right, over the
//    smaller inner dimension (mul(float1, float4x4) is the first row scaled; vkd3d's mul pins it).
//  - operators on matrices glslang computes otherwise than fxc (matrix_operators.h), in the same
//    expressions, compound assignments and `++`/`--`: generated helpers that compute row by row.
// An operand whose type differs is passed through a generated helper that builds the common type
// from its components (`fxport_shape_float3x2_to_float2x2(a)`, evaluated once, as before); the
// helpers go before the first function. Only where every operand's type is evident
// (expression_types.h); vectors glslang already truncates as fxc does, and matrices mixed with
// vectors in an intrinsic fxc refuses, so those stay as written.
#pragma once

#include <set>
#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> mixedShapeConversions(const EffectSyntax& syntax);

// The tokens of the `mul` calls mixedShapeConversions spells out: checks and rewrites made for
// glslang's mul (front_end_hazards, degenerate_matrices) leave them alone.
std::set<size_t> mulCallsSpelledOut(const EffectSyntax& syntax);

}  // namespace fxport::xlate
