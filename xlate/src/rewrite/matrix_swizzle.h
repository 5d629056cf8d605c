// Multi-component matrix swizzles (`View._m30_m31_m32`, `ViewInverse._41_42_43`) lowered to forms
// glslang 12's HLSL front end handles: it implements only single-element matrix swizzles and crashes
// (or reports "Missing functionality: matrix swizzle") on longer ones, which XNA samples use to read
// a camera position out of a view matrix.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fx/fx_syntax.h"
#include "fx/lexer.h"

namespace fxport::xlate {

struct MatrixSwizzleElement {
    int row = 0;  // zero-based
    int column = 0;
    std::string text;  // `_m30` or `_41`, as written
};

// The elements of `_m30_m31` / `_41_42` (not mixed within one swizzle, as fxc requires); nullopt
// if `swizzle` is not a matrix swizzle.
std::optional<std::vector<MatrixSwizzleElement>> parseMatrixSwizzle(const std::string& swizzle);

// Edits for every `.`-swizzle of two or more matrix elements (`_mRC` zero-based or `_RC` one-based):
//  - all elements in one row r:  `._m30_m31_m32` -> `[3].xyz` (a postfix like the original, so the
//    base expression is untouched, and it stays an l-value);
//  - otherwise, when read: `B._11_22_33` -> `float3(B._11, B._22, B._33)`, with B the postfix
//    expression before the dot (identifier, member, index and call chain), repeated per element;
//    a write (`m._m00_m11 = v`) is left to glslang, which handles it; a compound one
//    (`m._m00_m11 *= e`, which glslang refuses) becomes `m._m00_m11 = float2(m._m00, m._m11) * (e)`.
std::vector<TextEdit> lowerMatrixSwizzles(const std::vector<Token>& tokens);

}  // namespace fxport::xlate
