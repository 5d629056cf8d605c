// D3D10/11's out-of-range reads (spirv/out_of_range_accesses.h): a Load of a texel, level, slice
// or sample outside the resource, a typed UAV read and a structured or byte-address buffer read past
// the end read 0; GL leaves them undefined. The GLSL compares each coordinate against the resource's
// size and selects 0 (the GLSL before the pass: a bare texelFetch / imageLoad / buffer index).
#include <gtest/gtest.h>

#include <string>

#include "compile_loose.h"

using fxport::test::glslOfLoose;

namespace {

bool has(const std::string& glsl, const std::string& text) { return glsl.find(text) != std::string::npos; }

}  // namespace

TEST(OutOfRangeReads, TextureLoadComparesTexelAndLevelAgainstTheTexture) {
    const std::string glsl = glslOfLoose(
        "Texture2D t : register(t0);\n"
        "Texture2DArray a : register(t1);\n"
        "float4 main(float4 p : SV_Position, int m : TEXCOORD0) : SV_Target {\n"
        "    int2 c = int2(p.xy);\n"
        "    return t.Load(int3(c + int2(-1, 0), m)) + t.Load(int3(c, 0), int2(1, 1)) + a.Load(int4(c, 2, 0)) + t[c];\n"
        "}\n",
        "ps_5_0");
    EXPECT_TRUE(has(glsl, "textureSize(")) << glsl;
    EXPECT_TRUE(has(glsl, "textureQueryLevels(")) << glsl;  // the variable level m
    EXPECT_TRUE(has(glsl, "lessThan(uvec2(")) << glsl;     // unsigned: -1 is out of range
    EXPECT_TRUE(has(glsl, "lessThan(uvec3(")) << glsl;     // the array's slice too
    EXPECT_TRUE(has(glsl, "vec4(0.0)")) << glsl;
}

TEST(OutOfRangeReads, BufferAndMultisampleLoadsCompareIndexAndSample) {
    const std::string glsl = glslOfLoose(
        "Buffer<float4> b : register(t0);\n"
        "Texture2DMS<float4> ms : register(t1);\n"
        "float4 main(float4 p : SV_Position, int i : TEXCOORD0) : SV_Target {\n"
        "    return b.Load(i + 3) + b[i] + ms.Load(int2(p.xy), i);\n"
        "}\n",
        "ps_5_0");
    EXPECT_TRUE(has(glsl, "textureSize(")) << glsl;
    EXPECT_TRUE(has(glsl, "textureSamples(")) << glsl;
    EXPECT_TRUE(has(glsl, "vec4(0.0)")) << glsl;
}

TEST(OutOfRangeReads, TypedUavReadsCompareAgainstTheImage) {
    const std::string glsl = glslOfLoose(
        "RWTexture2D<float> img : register(u0);\n"
        "RWBuffer<uint> list : register(u1);\n"
        "[numthreads(8, 8, 1)] void main(uint3 id : SV_DispatchThreadID) {\n"
        "    img[id.xy] = img[id.xy + uint2(1, 0)] + list[id.x + 5];\n"
        "}\n",
        "cs_5_0");
    EXPECT_TRUE(has(glsl, "imageSize(")) << glsl;
    EXPECT_TRUE(has(glsl, "lessThan(")) << glsl;
}

TEST(OutOfRangeReads, StructuredAndByteAddressReadsCompareAgainstTheLength) {
    const std::string glsl = glslOfLoose(
        "struct P { float3 pos; float r; };\n"
        "StructuredBuffer<P> parts : register(t0);\n"
        "ByteAddressBuffer raw : register(t1);\n"
        "RWStructuredBuffer<float> outv : register(u0);\n"
        "[numthreads(64, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {\n"
        "    outv[id.x] = parts[id.x + 1].r + parts[id.x].pos.y + asfloat(raw.Load(id.x * 4 + 8));\n"
        "}\n",
        "cs_5_0");
    EXPECT_TRUE(has(glsl, ".length()")) << glsl;
    EXPECT_TRUE(has(glsl, "? ")) << glsl;
}

// RWStructuredBuffer / RWByteAddressBuffer stores and atomics past the end are dropped (GL may
// write whatever memory follows): each runs under `if (index < length())`; a dropped atomic's
// original value is 0.
TEST(OutOfRangeReads, BufferWritesAndAtomicsRunOnlyInsideTheBuffer) {
    const std::string glsl = glslOfLoose(
        "RWStructuredBuffer<float2> outv : register(u0);\n"
        "RWByteAddressBuffer counts : register(u1);\n"
        "[numthreads(64, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {\n"
        "    uint before;\n"
        "    counts.InterlockedAdd(id.x * 4, 1, before);\n"
        "    for (uint k = 0; k < id.y; ++k) outv[id.x + k] = float2(before, k);\n"
        "    counts.Store(id.x * 4 + 256, before);\n"
        "}\n",
        "cs_5_0");
    EXPECT_TRUE(has(glsl, "if (")) << glsl;
    EXPECT_TRUE(has(glsl, "outv_1._data.length()")) << glsl;
    EXPECT_TRUE(has(glsl, "counts_1._data.length()")) << glsl;
    EXPECT_TRUE(has(glsl, "atomicAdd(")) << glsl;
}

// A whole struct or matrix element read past the end reads zeros (under the same `if`: OpSelect
// cannot choose a struct in SPIR-V 1.0), and a store to a member of an element is guarded too.
TEST(OutOfRangeReads, WholeElementReadsAndMemberStoresAreGuarded) {
    const std::string glsl = glslOfLoose(
        "struct P { float3 pos; float r; float4x4 m; };\n"
        "StructuredBuffer<P> parts : register(t0);\n"
        "RWStructuredBuffer<P> outp : register(u0);\n"
        "StructuredBuffer<float4x4> mats : register(t1);\n"
        "[numthreads(64, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {\n"
        "    P p = parts[id.x + 3];\n"
        "    p.pos += mul(mats[id.y], float4(1, 2, 3, 4)).xyz;\n"
        "    outp[id.x] = p;\n"
        "}\n",
        "cs_5_0");
    EXPECT_TRUE(has(glsl, "< uint(parts_1._data.length())")) << glsl;
    EXPECT_TRUE(has(glsl, "P(vec3(0.0), 0.0, mat4(")) << glsl;
    EXPECT_TRUE(has(glsl, "< uint(mats_1._data.length())")) << glsl;
    EXPECT_TRUE(has(glsl, "if (gl_GlobalInvocationID.x < uint(outp_1._data.length()))")) << glsl;
}

// A loop whose body the optimiser merged into its header (a do-while without branches): the store
// and atomic there are guarded too (the header keeps its phis and merge instruction, the rest
// moves to a block of its own, which is split like any other).
TEST(OutOfRangeReads, AccessesInLoopHeadersAreGuarded) {
    const std::string glsl = glslOfLoose(
        "RWStructuredBuffer<uint> o : register(u0);\n"
        "RWByteAddressBuffer r : register(u1);\n"
        "cbuffer C : register(b0) { uint n; };\n"
        "[numthreads(64, 1, 1)] void main(uint3 id : SV_DispatchThreadID) {\n"
        "    uint i = id.x;\n"
        "    do { o[i] = i; uint prev; r.InterlockedMax(i * 4, i, prev); i += prev + n; } while (i < 100);\n"
        "}\n",
        "cs_5_0");
    EXPECT_TRUE(has(glsl, "< uint(o_1._data.length()))")) << glsl;
    EXPECT_TRUE(has(glsl, "< uint(r_1._data.length()))")) << glsl;
}
