// HLSL numeric types by name: float4 -> 1x4, float3x3 -> 3x3 matrix, vector<int,2>, matrix<float,4,4>.
#pragma once

#include <string>

namespace fxport::xlate {

struct BasicType {
    std::string scalar;  // float, half, int, uint, bool, double, dword, min16float ...
    int rows = 1;        // > 1 only for matrices
    int columns = 1;     // vector size or matrix columns
    bool isMatrix = false;
    bool ok = false;     // false: not a numeric type (a struct, an object ...)
};

BasicType describeBasicType(const std::string& type);

}  // namespace fxport::xlate
