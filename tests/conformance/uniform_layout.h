// Where vkd3d's `uniform N ...` lands: N counts 32-bit components of the constant buffer bound at
// slot 0 (SM4+: D3D10 cbuffer packing) or of the float constant registers (SM2/3: c(N/4)). fxport
// sets parameters by name, so this computes each parameter's D3D offset from the reflection
// (declaration order, class, rows, columns, elements, packing rules) -- independently of the
// layout fxport itself chose for GL -- and maps every scalar of the parameter to one.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace fxport::xlate {
struct CompiledEffect;
struct Parameter;
}

namespace conformance {

struct ParameterPlacement {
    int parameter = -1;              // index into CompiledEffect::parameters
    // A struct's member (of element i of an array of structs): the steps from the parameter,
    // (a member?, index), as EffectParameter's StructureMembers()[k] / Elements()[i] take them,
    // and the member's reflection. Empty / the parameter itself for a numeric parameter.
    std::vector<std::pair<bool, int>> path;
    const fxport::xlate::Parameter* leaf = nullptr;
    std::vector<int> scalarOffsets;  // D3D component offset of scalar k (row by row, element by element)
    bool settable = true;            // false: a struct or a type the runtime cannot set
    std::string why;                 // when not settable
};

struct UniformLayout {
    std::vector<ParameterPlacement> placements;
    std::string guess;  // non-empty when fxc's placement could not be known for sure (why)
};

// `source` is the HLSL of the shaders (for explicit register(cN)/packoffset, which the reflection
// does not carry). `model` 20/30 = D3D9 registers, 40+ = cbuffer packing.
UniformLayout computeUniformLayout(const fxport::xlate::CompiledEffect& effect, const std::string& source, int model);

// Non-empty when the shaders read constant-buffer bytes that no parameter of the reflection covers
// (a struct or unnamed global fxport does not list): then no `uniform` can reach them by name.
std::string uncoveredUniformRead(const fxport::xlate::CompiledEffect& effect);

}  // namespace conformance
