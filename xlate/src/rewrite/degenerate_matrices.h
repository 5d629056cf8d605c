// Matrices with one row or one column (float1x4, float4x1, float1x1, matrix<float, 1, 3>) as fxc
// means them: glslang 12 has no constructor for them ("cannot construct this type"), crashes on
// some uses, and SPIR-V has no matrix of one column. fxc converts them freely to and from vectors
// of as many components (returns, arguments, assignments, casts), so where their layout does not
// matter (function bodies, parameters without a semantic, return types, static globals) they become
// those vectors (float1x1: float), and indexing follows: `m[0]` of a 1xN is the whole row (the
// vector), `m[i][0]` of an Nx1 is component i (`m[i]`).
// Parameters and return types become vectors too, with a semantic or not: the entry wrapper lays
// the vector onto the matrix's semantic registers (signature_layout.h).
// Left as they are: uniforms and struct members (their register layout is a matrix's), and
// variables used where a vector means something else:
// an indexed group `(c ? a : b)[0]`, a 1xN second or Nx1 first argument of mul (fxc's outer
// product).
#pragma once

#include <string>
#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> degenerateMatricesAsVectors(const EffectSyntax& syntax);

// `type` as the rewritten source spells a parameter or return of it: `float4x1` and `float1x4`
// -> `float4`, `float1x1` -> `float`; any other type as written.
std::string degenerateAsVector(const std::string& type);

// The return type of `entry` as the rewritten source has it (degenerateAsVector).
std::string entryReturnType(const EffectSyntax& syntax, const FxFunction& entry);

}  // namespace fxport::xlate
