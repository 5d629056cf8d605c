// What fxc accepts and refuses in shader model 2.0/3.0 code (the profiles of every XNA 4 effect)
// where it differs from SM 4+, each pinned against the rule vkd3d's conformance suite shows.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "compile_loose.h"

using namespace fxport;
using namespace fxport::test;

// A texture's Sample maps onto tex2D below SM 4, but Load (and GetDimensions, Gather, SampleCmp
// ...) has no D3D9 instruction: fxc refuses it in ps_2_0/ps_3_0 (vkd3d combined-samplers L148),
// at the method, also through an array element and in a function the entry calls; ps_4_0 takes it.
TEST(ShaderModel3, Sm4TextureMethodsAreRefusedBelowSm4) {
    const std::string source =
        "Texture2D tex;\nTexture2D arr[2];\nsampler sam;\n"
        "float4 dims() { uint w, h; tex.GetDimensions(w, h); return w; }\n"
        "float4 main() : COLOR\n{\n"
        "    return tex.Load(int3(0, 0, 0)) + arr[1].Load(int3(0, 0, 0)) + tex.Sample(sam, float2(0, 0)) + dims();\n}\n";
    for (const char* profile : {"ps_2_0", "ps_3_0"}) {
        const std::vector<xlate::Diagnostic> errors = errorsOfLoose(source, profile);
        ASSERT_EQ(errors.size(), 3u) << profile;
        EXPECT_EQ(errors[0].location.line, 4);
        EXPECT_NE(errors[0].message.find("'GetDimensions' of texture 'tex' has no " + std::string(profile) + " instruction"), std::string::npos)
            << errors[0].message;
        EXPECT_EQ(errors[1].location.line, 7);
        EXPECT_NE(errors[1].message.find("'Load' of texture 'tex'"), std::string::npos) << errors[1].message;
        EXPECT_NE(errors[2].message.find("'Load' of texture 'arr'"), std::string::npos) << errors[2].message;
        EXPECT_NE(errors[2].message.find("X4532"), std::string::npos);
    }
    EXPECT_FALSE(glslOfLoose(source, "ps_4_0").empty());
    EXPECT_FALSE(glslOfLoose("Texture2D tex;\nsampler sam;\nfloat4 main() : COLOR { return tex.Sample(sam, float2(0, 0)); }\n", "ps_3_0").empty());
}
