// HLSL's int, uint and bool matrices (int2x2, uint3x4, bool2x2) as arrays of their columns.
//
// glslang's HLSL front end gives them an OpTypeMatrix of integer or bool vectors, which SPIR-V does
// not allow and SPIRV-Cross writes out as `imat2`, a type GLSL does not have: the driver refuses
// the shader. An array of the column vectors holds the same values and is taken by every
// operation that only moves a value (load, store, access chains, composites); the operations that
// compute on one (conversions, arithmetic, transpose) are done column by column here.
// A constant buffer holding such a matrix is flattened to registers first (cbuffer_packing.h), so
// no array stands in a GLSL uniform block where D3D's column_major layout would differ.
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

// A pass of parsed_spirv.h; false (module unchanged) when it has no such matrix.
bool integerMatricesAsArrays(ParsedSpirv& m);

}  // namespace fxport::xlate
