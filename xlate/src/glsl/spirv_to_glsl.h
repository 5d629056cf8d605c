// Step 4b/5: SPIR-V -> GLSL 4.50 core with SPIRV-Cross, plus reflection of what the shader uses.
// Here the D3D conventions that live in bindings and locations are fixed:
//   - the effect's constant buffer ($Global) is UBO binding 0, fxport's internal block binding 1,
//     user cbuffers 2 + their declaration order; every block is laid out as D3D packs it
//     (cbuffer_packing.h), as a register array where GLSL cannot declare D3D's offsets, and only
//     where that rewrite cannot follow the shader, re-laid out with std140 rules (d3dPacking false);
//   - a sampler's binding is its texture unit (DX9 register / DX10 texture register);
//   - a varying's location is a fixed function of its semantic (TEXCOORDn -> n, COLORn -> 16+n ...),
//     so any vertex and pixel shader with matching semantics link, whichever effect they come from;
//   - vertex inputs get locations in order, and the reflection names their semantics.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "rewrite/fx_rewrite.h"

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
    std::vector<UniformMember> members;  // a struct's (or struct array's) members, offsets from its start
};

// A uniform block as one shader declares it ($Global or a user cbuffer; not fxport's internal one).
struct UniformBlockLayout {
    std::string name;
    int index = 0;  // in CompiledEffect::uniformBlocks: $Global 0, cbuffer k (declaration order) 1 + k
    int size = 0;
    std::vector<UniformMember> members;
    bool d3dPacking = false;  // members at D3D's offsets (false: re-laid out with std140)
};

struct GlslShader {
    std::string glsl;
    std::string error;        // non-empty = failed
    std::string unsupported;  // non-empty = needs more than GL gives (FX1404), e.g. texture units
    std::vector<VertexInput> inputs;
    std::vector<SamplerBinding> samplers;
    // Per sampler binding, the SPIR-V id of the variable it samples (the texture of a pair). glslang
    // numbers globals as the code first uses them, so ids order the bindings by first use.
    std::vector<std::uint32_t> samplerFirstUse;
    std::vector<UniformBlockLayout> blocks;  // the blocks this shader reads, as it declares them
    std::vector<std::string> membersRead;    // block members with active ranges (any block)
    std::vector<UniformRange> rangesRead;
    std::vector<UniformRange> rangesLive;  // the bytes whose values reach a result (live_uniform_bytes.h)
    int outputTargets = 0;
    bool writesDepth = false;
    int clipDistances = 0;  // the size of the gl_ClipDistance output (non-pixel stages)
    std::vector<Varying> varyingInputs, varyingOutputs;
    std::vector<ShaderOutput> outputs;   // non-pixel stages: what stream output may capture
    int outputPrimitiveVertices = 0;      // geometry: 1 points, 2 line strips, 3 triangle strips
    std::vector<StorageBinding> storage;   // SSBOs and images (UAVs, buffer SRVs)
    std::array<int, 3> threadGroupSize{};  // compute: the SPIR-V LocalSize
};

// `hull`: for a domain shader, the attributes of the pass's hull shader. D3D declares partitioning
// and output topology on the hull shader, GL on the tessellation evaluation shader (its
// spacing / vertex order / point_mode), so the domain shader's GLSL takes them from there.
GlslShader spirvToGlsl(std::vector<std::uint32_t> spirv, ShaderStage stage, const RewrittenEffect& effect,
                       VaryingLocations& varyings, const Tessellation* hull = nullptr);

}  // namespace fxport::xlate
