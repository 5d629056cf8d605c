// The t# and s# registers xlate reflects for D3D10+ shaders (SamplerBinding::textureRegister /
// samplerRegister, xlate/src/effect/d3d_registers.h) are fxc's. The expected values are the RDEF
// tables and probes of vkd3d's texture-ordering and combined-samplers tests (fxc's output): a
// texture fxc makes for a DX9 sampler comes before the declared textures, by decreasing bind
// count, ties by first use; sampler arrays come before single samplers.
#include <gtest/gtest.h>

#include <string>

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
