// The t# and s# registers xlate reflects for D3D10+ shaders (SamplerBinding::textureRegister /
// samplerRegister, xlate/src/effect/d3d_registers.h) are fxc's. The expected values are the RDEF
// tables and probes of vkd3d's texture-ordering and combined-samplers tests (fxc's output): a
// texture fxc makes for a DX9 sampler comes before the declared textures, by decreasing bind
// count, ties by first use; sampler arrays come before single samplers.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "fxport/xlate/effect_compiler.h"

using namespace fxport::xlate;

namespace {

CompiledEffect compile(const std::string& declarations, const std::string& body) {
    CompileOptions o;
    o.useCache = false;
    return compileEffectSource(declarations + "float4 PS() : SV_Target { " + body +
                                   " }\ntechnique10 T { pass P { SetPixelShader(CompileShader(ps_4_0, PS())); } }\n",
                               "virtual/D3dRegisters.fx", o);
}

// The binding that samples with `sampler` (fxport's name: `sam_fxport_1` is element 1 of `sam[]`)
// or, where `sampler` is empty, reads `texture`.
const SamplerBinding& binding(const CompiledEffect& e, const std::string& sampler, const std::string& texture = {}) {
    for (const auto& b : e.shaders.at(0).samplers)
        if (sampler.empty() ? b.textureParameter == texture : b.samplerName == sampler) return b;
    throw std::runtime_error("no binding for " + sampler + texture);
}

}  // namespace

// texture-ordering.shader_test's first shader and its RDEF table.
TEST(D3dRegisters, SamplerTexturesByBindCountThenDeclaredTextures) {
    CompiledEffect e = compile(
        "Texture2D tex;\nTexture2D texs[2];\nsampler samA;\nsampler samB;\nsampler sam_arr_10[2];\nsampler sam_arr_01[2];\nsampler sam_arr_11[2];\n",
        "float4 f = 0;\n"
        "f += 100 * tex2D(samB, float2(0, 0)); f += 10 * tex2D(sam_arr_10[0], float2(0, 0)); f += tex2D(sam_arr_11[0], float2(0, 0));\n"
        "f += 100 * tex2D(sam_arr_11[1], float2(0, 0)); f += 10 * tex2D(sam_arr_01[1], float2(0, 0)); f += texs[1].Load(int3(0, 0, 0));\n"
        "f += 100 * texs[0].Load(int3(0, 0, 0)); f += 10 * tex.Load(int3(0, 0, 0)); f += tex2D(samA, float2(0, 0));\n"
        "return f;");
    ASSERT_FALSE(e.hasErrors());
    // sam_arr_11 t0 (bind count 2, first used before sam_arr_01), sam_arr_01 t2, samB t4,
    // sam_arr_10 t5, samA t6, then tex t7, texs t8.
    EXPECT_EQ(binding(e, "sam_arr_11_fxport_0").textureRegister, 0);
    EXPECT_EQ(binding(e, "sam_arr_11_fxport_1").textureRegister, 1);
    EXPECT_EQ(binding(e, "sam_arr_01_fxport_1").textureRegister, 3);
    EXPECT_EQ(binding(e, "samB").textureRegister, 4);
    EXPECT_EQ(binding(e, "sam_arr_10_fxport_0").textureRegister, 5);
    EXPECT_EQ(binding(e, "samA").textureRegister, 6);
    EXPECT_EQ(binding(e, "", "tex").textureRegister, 7);
    EXPECT_EQ(binding(e, "", "texs").textureRegister, 8);
    EXPECT_EQ(binding(e, "", "texs").elements, 2);
    // Samplers: the arrays in declaration order (each as wide as its bind count), then samA, samB.
    EXPECT_EQ(binding(e, "sam_arr_10_fxport_0").samplerRegister, 0);
    EXPECT_EQ(binding(e, "sam_arr_01_fxport_1").samplerRegister, 2);
    EXPECT_EQ(binding(e, "sam_arr_11_fxport_1").samplerRegister, 4);
    EXPECT_EQ(binding(e, "samA").samplerRegister, 5);
    EXPECT_EQ(binding(e, "samB").samplerRegister, 6);
}

// texture-ordering's fourth shader: a sampler-made texture is as wide as its bind count, a used
// texture array as wide as the whole array.
TEST(D3dRegisters, DeclaredArraysTakeAllTheirElements) {
    CompiledEffect e = compile("sampler sam;\nTexture2D texs[3];\nsampler sam_arr[3];\nTexture2D tex;\n",
                               "return 100 * texs[0].Sample(sam, float2(0, 0)) + 10 * tex2D(sam_arr[1], float2(0, 0)) + tex.Sample(sam, float2(0, 0));");
    ASSERT_FALSE(e.hasErrors());
    EXPECT_EQ(binding(e, "sam_arr_fxport_1").textureRegister, 1);  // sam_arr t0, 2 wide
    EXPECT_EQ(binding(e, "sam_arr_fxport_1").samplerRegister, 1);  // sam_arr s0, 2 wide
    int texs = -1, tex = -1;
    for (const auto& b : e.shaders.at(0).samplers) {
        if (b.textureParameter == "texs") texs = b.textureRegister;
        if (b.textureParameter == "tex") tex = b.textureRegister;
        if (b.samplerName == "sam") {
            EXPECT_EQ(b.samplerRegister, 2);
        }
    }
    EXPECT_EQ(texs, 2);
    EXPECT_EQ(tex, 5);
}

// combined-samplers: "On sm4, textures for new separated samplers are allocated before regular
// textures": tex2D(sam) beside tex.Sample(sam) reads t0, tex is t1.
TEST(D3dRegisters, ATextureMadeForASamplerComesFirst) {
    CompiledEffect e = compile("Texture2D tex;\nsampler sam;\n", "return 10 * tex.Sample(sam, float2(0, 0)) + tex2D(sam, float2(0, 0));");
    ASSERT_FALSE(e.hasErrors());
    int made = -1, declared = -1;
    for (const auto& b : e.shaders.at(0).samplers) {
        if (b.textureParameter == "tex") declared = b.textureRegister;
        if (b.textureParameter.find("sam_fxport_texture") == 0) made = b.textureRegister;
        if (b.samplerName == "sam") {
            EXPECT_EQ(b.samplerRegister, 0);
        }
    }
    EXPECT_EQ(made, 0);
    EXPECT_EQ(declared, 1);
}

// register-reservations-profile and -resources (fxc's probes in a ps_4_0 shader): a reservation
// for another stage or profile binds nothing, ps_4_0's holds, and so does one of its own class only.
TEST(D3dRegisters, ReservationsForOtherProfilesOrClassesAreIgnored) {
    auto registerOf = [](const std::string& declaration) {
        CompiledEffect e = compile(declaration, "return tex1.Load(int3(0, 0, 0));");
        EXPECT_FALSE(e.hasErrors()) << declaration;
        return binding(e, "", "tex1").textureRegister;
    };
    EXPECT_EQ(registerOf("Texture2D tex1 : register(vs, t1);\n"), 0);
    EXPECT_EQ(registerOf("Texture2D tex1 : register(ps_4_1, t1);\n"), 0);
    EXPECT_EQ(registerOf("Texture2D tex1 : register(ps, t1);\n"), 1);
    EXPECT_EQ(registerOf("Texture2D tex1 : register(ps_4_1, t1) : register(ps_4_0, t2);\n"), 2);
    EXPECT_EQ(registerOf("Texture2D tex1 : register(ps, t1) : register(ps_5_0, t2);\n"), 1);
    EXPECT_EQ(registerOf("Texture2D tex1 : register(ps, t[1]);\n"), 1);
    EXPECT_EQ(registerOf("Texture2D unused : register(s0);\nTexture2D tex1;\n"), 0);
    EXPECT_EQ(registerOf("Texture2D unused[2][2] : register(t0);\nTexture2D tex1;\n"), 4);
}


namespace {

CompiledEffect compileSm3(const std::string& declarations, const std::string& body) {
    CompileOptions o;
    o.useCache = false;
    return compileEffectSource(declarations + "float4 PS() : COLOR { " + body + " }\ntechnique T { pass P { PixelShader = compile ps_3_0 PS(); } }\n",
                               "virtual/D3d9Registers.fx", o);
}

// The SM 1-3 binding that samples `texture` with `sampler` (a DX9 sampler's own texture when empty).
const SamplerBinding& d3d9Binding(const CompiledEffect& e, const std::string& sampler, const std::string& texture = {}) {
    for (const auto& b : e.shaders.at(0).samplers)
        if (b.samplerName == sampler &&
            (texture.empty() ? b.textureParameter.empty() || b.textureParameter.find("_fxport_texture") != std::string::npos : b.textureParameter == texture))
            return b;
    throw std::runtime_error("no binding for " + sampler + "+" + texture);
}

}  // namespace

// SM 1-3: one s# (also the texture stage) per DX9 sampler and per combined `tex.Sample(sam, uv)`.
// The values are combined-samplers.shader_test's sm<4 probes (fxc's output), each a weighted sum
// of [srv N] = N: e.g. 453021 reads s4, s5, s3, s0, s2, s1.
TEST(D3d9Registers, CombinedSamplersComeBeforeTheSamplersOfTheirWidth) {
    // "On sm1, textures for new combined samplers are allocated before regular samplers":
    // 10 * tex.Sample(sam) + tex2D(sam) probes 1, so the combined sampler is s0 and sam s1.
    CompiledEffect e = compileSm3("Texture2D tex;\nsampler sam;\n", "return 10 * tex.Sample(sam, float2(0, 0)) + tex2D(sam, float2(0, 0));");
    ASSERT_FALSE(e.hasErrors());
    EXPECT_EQ(d3d9Binding(e, "sam", "tex").samplerRegister, 0);
    EXPECT_EQ(d3d9Binding(e, "sam", "tex").textureRegister, 0);
    EXPECT_EQ(d3d9Binding(e, "sam").samplerRegister, 1);
    EXPECT_EQ(d3d9Binding(e, "sam").textureRegister, 1);
}

// combined-samplers' samA/samB/samC shader (probe 453021): the combined samplers take s0-s2 in
// their samplers' declaration order (A, B, C), not their order of use (A, C, B); the DX9 samplers
// then s3-s5, also by declaration.
TEST(D3d9Registers, CombinedThenDx9SamplersEachInDeclarationOrder) {
    CompiledEffect e = compileSm3("sampler samA;\nsampler samB;\nsampler samC;\ntexture2D tex;\n",
                                  "return 100000 * tex2D(samB, float2(0, 0)) + 10000 * tex2D(samC, float2(0, 0)) + 1000 * tex2D(samA, float2(0, 0))"
                                  " + 100 * tex.Sample(samA, float2(0, 0)) + 10 * tex.Sample(samC, float2(0, 0)) + tex.Sample(samB, float2(0, 0));");
    ASSERT_FALSE(e.hasErrors());
    EXPECT_EQ(d3d9Binding(e, "samA", "tex").samplerRegister, 0);
    EXPECT_EQ(d3d9Binding(e, "samB", "tex").samplerRegister, 1);
    EXPECT_EQ(d3d9Binding(e, "samC", "tex").samplerRegister, 2);
    EXPECT_EQ(d3d9Binding(e, "samA").samplerRegister, 3);
    EXPECT_EQ(d3d9Binding(e, "samB").samplerRegister, 4);
    EXPECT_EQ(d3d9Binding(e, "samC").samplerRegister, 5);
}

// combined-samplers' texA/samA[2]/texB[2]/samB shader (probe 4351): wider objects first. The
// combined texB[].Sample(samB) is as wide as texB (s0-s1, texB[1] at s1), samA[] as its bind count
// (s2-s3); then the combined texA.Sample(samA[0]) s4 before samB s5. And sam[2] beside a combined
// sampler (probe 21): sam[] s0-s1, the combined one s2.
TEST(D3d9Registers, WiderSamplersAndArraysComeFirst) {
    CompiledEffect e = compileSm3("Texture2D texA;\nsampler samA[2];\nTexture2D texB[2];\nsampler samB;\n",
                                  "return 1000 * texA.Sample(samA[0], float2(0, 0)) + 100 * tex2D(samA[1], float2(0, 0))"
                                  " + 10 * tex2D(samB, float2(0, 0)) + texB[1].Sample(samB, float2(0, 0));");
    ASSERT_FALSE(e.hasErrors());
    EXPECT_EQ(d3d9Binding(e, "samB", "texB").samplerRegister, 0);
    EXPECT_EQ(d3d9Binding(e, "samB", "texB").elements, 2);
    EXPECT_EQ(d3d9Binding(e, "samA_fxport_1").samplerRegister, 3);
    EXPECT_EQ(d3d9Binding(e, "samA_fxport_0", "texA").samplerRegister, 4);
    EXPECT_EQ(d3d9Binding(e, "samB").samplerRegister, 5);

    CompiledEffect arrays = compileSm3("Texture2D tex;\nsampler sam[2];\n", "return 10 * tex.Sample(sam[0], float2(0, 0)) + tex2D(sam[1], float2(0, 0));");
    ASSERT_FALSE(arrays.hasErrors());
    EXPECT_EQ(d3d9Binding(arrays, "sam_fxport_1").samplerRegister, 1);
    EXPECT_EQ(d3d9Binding(arrays, "sam_fxport_0", "tex").samplerRegister, 2);
}

// Past s15 (D3D9's last sampler register; fxc refuses such a shader, fxport's GL units reach
// further) a shader keeps no registers and binds by unit, as before: it still compiles.
TEST(D3d9Registers, PastS15NoRegistersAreGiven) {
    std::string declarations, body = "float4 f = 0;";
    for (int i = 0; i < 17; ++i) {
        declarations += "sampler s" + std::to_string(i) + ";\n";
        body += " f += tex2D(s" + std::to_string(i) + ", float2(0, 0));";
    }
    CompiledEffect e = compileSm3(declarations, body + " return f;");
    ASSERT_FALSE(e.hasErrors());
    for (const auto& b : e.shaders.at(0).samplers) {
        EXPECT_EQ(b.samplerRegister, -1) << b.samplerName;
        EXPECT_EQ(b.textureRegister, -1) << b.samplerName;
    }
}

// uav-rwtexture L158: an array of UAVs takes one u# per element from its register on, each fed
// from its own slot (element 1 of `u[2] : register(u2)` is u3, GL image unit 3); an array
// without a register takes the first run of free registers long enough for all its elements.
TEST(D3dRegisters, UavArraysTakeOneRegisterPerElement) {
    CompileOptions o;
    o.useCache = false;
    CompiledEffect e = compileEffectSource(
        "RWTexture2D<float4> u[2] : register(u2);\nRWBuffer<float> v;\nRWTexture2D<float> w[2];\n"
        "[numthreads(1, 1, 1)] void CS() { u[0][uint2(0, 0)] = 1; u[1][uint2(0, 0)] = 2; v[0] = 3; w[0][uint2(0, 0)] = 4; w[1][uint2(0, 0)] = 5; }\n"
        "technique11 T { pass P { SetComputeShader(CompileShader(cs_5_0, CS())); } }\n",
        "virtual/UavArrays.fx", o);
    ASSERT_FALSE(e.hasErrors());
    std::vector<std::string> got;
    for (const auto& b : e.shaders.at(0).storage)
        got.push_back(b.name + " u" + std::to_string(b.slot) + " @" + std::to_string(b.binding));
    EXPECT_EQ(got, (std::vector<std::string>{"u[0] u2 @2", "u[1] u3 @3", "v u0 @0", "w[0] u4 @4", "w[1] u5 @5"}));
}
