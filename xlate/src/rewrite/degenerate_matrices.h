// Matrices with one row or one column (float1x4, float4x1, float1x1, matrix<float, 1, 3>) as fxc
// means them: glslang 12 has no constructor for them ("cannot construct this type"), crashes on
// some uses, and SPIR-V has no matrix of one column. fxc converts them freely to and from vectors
// of as many components (returns, arguments, assignments, casts), so where their layout does not
// matter (function bodies, parameters without a semantic, return types, static globals) they become
// those vectors (float1x1: float), and indexing follows: `m[0]` of a 1xN is the whole row (the
// vector), `m[i][0]` of an Nx1 is component i (`m[i]`).
// Parameters and return types become vectors too, with a semantic or not: the entry wrapper lays
// the vector onto the matrix's semantic registers (signature_layout.h).
// A uniform (a non-static global, not an array) keeps D3D's matrix layout, a register per column
// (column_major) or per row (row_major), in storage glslang can lay out: an array of registers,
// `float1x3 m` (column_major) -> `float m[3]`, `float3x1 m` -> `float3 m[1]`, whose D3D packing is
// the matrix's (each element starts a register; cbuffer_packing.h). Each use of it in a function
// body is the vector read from there: `float3(m[0], m[1], m[2])`, `m[0]`.
// Left as they are: struct members and uniform arrays (their register layout is a matrix's), and
// variables used where a vector means something else:
// an indexed group `(c ? a : b)[0]`, a 1xN second or Nx1 first argument of mul (fxc's outer
// product).
#pragma once

#include <string>
#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

// `defaultMajority`: CompileOptions::defaultMatrixMajority (the majority before any pragma).
// `swizzles`, where given, gets the edits of matrix swizzles of such variables (`m._m01_m02` ->
// `m.yz`), which must go ahead of matrix_swizzle.h's edits of the same tokens.
std::vector<TextEdit> degenerateMatricesAsVectors(const EffectSyntax& syntax, const std::string& defaultMajority = {},
                                                 std::vector<TextEdit>* swizzles = nullptr);

// Such a uniform's storage: `registers` elements of `perRegister` components each, and the
// majority D3D lays it out in (its own modifier, else the latest `#pragma pack_matrix` before it,
// else `defaultMajority`, else column_major).
struct VectorUniformStorage {
    int registers = 1;
    int perRegister = 1;
    bool rowMajor = false;
};
VectorUniformStorage vectorUniformStorage(const EffectSyntax& syntax, const FxGlobal& g, const std::string& defaultMajority);

// `type` as the rewritten source spells a parameter or return of it: `float4x1` and `float1x4`
// -> `float4`, `float1x1` -> `float`; any other type as written.
std::string degenerateAsVector(const std::string& type);

// The return type of `entry` as the rewritten source has it (degenerateAsVector).
std::string entryReturnType(const EffectSyntax& syntax, const FxFunction& entry);

}  // namespace fxport::xlate
