// Step 4b/5: SPIR-V -> GLSL 4.50 core with SPIRV-Cross, plus reflection of what the shader uses.
// Here the D3D conventions that live in bindings and locations are fixed:
//   - the effect's constant buffer ($Global) is UBO binding 0, fxport's internal block binding 1;
//   - a sampler's binding is its texture unit (DX9 register / DX10 texture register);
//   - a varying's location is a fixed function of its semantic (TEXCOORDn -> n, COLORn -> 16+n ...),
//     so any vertex and pixel shader with matching semantics link, whichever effect they come from;
//   - vertex inputs get locations in order, and the reflection names their semantics.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "fx_rewrite.h"

namespace fxport::xlate {

// Effect-wide map for semantics outside the fixed table (DX10 allows any name): each new one gets
// the next free location, the same in every shader of the effect.
class VaryingLocations {
public:
    int locationOf(const std::string& semantic);  // upper-case semantic with index, e.g. TEXCOORD3
private:
    std::map<std::string, int> custom_;
};

struct UniformMember {
    std::string name;
    int offset = 0;
    int size = 0;
    int matrixStride = 0;
    int arrayStride = 0;
    bool hlslRowMajor = false;  // HLSL packing (SPIR-V decorates the transposed matrix)
};

struct GlslShader {
    std::string glsl;
    std::string error;  // non-empty = failed
    std::vector<VertexInput> inputs;
    std::vector<SamplerBinding> samplers;
    std::vector<UniformMember> globalMembers;  // layout of $Global as this shader sees it
    int globalSize = 0;
    std::vector<std::string> membersRead;      // $Global members with active ranges
    std::vector<UniformRange> rangesRead;
    int outputTargets = 0;
    bool writesDepth = false;
};

GlslShader spirvToGlsl(std::vector<std::uint32_t> spirv, ShaderStage stage, const RewrittenEffect& effect,
                       VaryingLocations& varyings);

}  // namespace fxport::xlate
