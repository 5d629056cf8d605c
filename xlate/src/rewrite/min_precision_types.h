// Minimum-precision type names glslang's HLSL front end does not take, as their 32-bit types:
// the component type of vector<T, N> / matrix<T, R, C> (`half`, `min16float`, `min10float`,
// `min16int`, `min12int`, `min16uint`) and the matrix names (`min16float4x4`, `min16int2x2`, ...;
// Windows-universal-samples' HolographicSpatialMapping). glslang already makes `min16float` and
// its vectors float; fxc stores minimum-precision values as 32-bit ones in constant buffers.
#pragma once

#include <string>

#include "fx/lexer.h"

namespace fxport::xlate {

// "float", "int" or "uint" for a minimum-precision scalar name (and `half`), else nullptr.
const char* fullPrecisionScalar(const std::string& name);

// `float4x4` for the token `min16float4x4` (and the other minimum-precision matrix names), else "".
std::string fullPrecisionMatrixName(const Token& t);
// The same for a type name as text (`min16uint4x2` -> `uint4x2`): a rewrite that spells a
// constructor of a declared type writes it so.
std::string fullPrecisionMatrixName(const std::string& name);

}  // namespace fxport::xlate
