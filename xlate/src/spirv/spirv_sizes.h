// Sizes of what a shader declares, read from its SPIR-V before SPIRV-Cross and the GL driver see
// it. Array limits checked on the source text miss arrays behind typedefs and arrays nested in
// struct arrays, and SPIRV-Cross's std140 relayout computes sizes in 32 bits, so a constant of
// 2^32 bytes wrapped to 0 and compiled; a local `float4 a[10000000]` compiled and cost the GL
// driver gigabytes at load. Here every variable's size is computed in 64 bits (saturating) through
// typedefs, structs and nested arrays, and checked against limits::kMaxVariableBytes and
// limits::kMaxArrayElements (docs/limits.md, FX1204).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fxport::xlate {

struct OversizedVariable {
    std::string name;          // the global, cbuffer member or local as the source names it
    std::uint64_t bytes = 0;   // its size, 16-byte registers per array element as D3D packs them
    std::uint64_t elements = 0;  // array elements in all, nested arrays multiplied
    std::uint64_t length = 0;  // its outermost array length, when it is an array (to find a local by)
    std::string block;         // set when the whole constant buffer is too large: `name` is its largest member
};

// The first variable (or member of a constant buffer) past a limit, if any.
std::optional<OversizedVariable> findOversizedVariable(const std::vector<std::uint32_t>& words);

}  // namespace fxport::xlate
