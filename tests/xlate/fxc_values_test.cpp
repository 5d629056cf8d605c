// Issue 23: values fxc gives where glslang, left alone, computes others. Each case is a section of
// vkd3d's conformance suite (file and line named), whose probe is native D3D's value; the constant
// the translated pixel shader returns is read from its GLSL (SPIRV-Cross folds it to a literal).
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "fxport/xlate/effect_compiler.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

namespace {

std::string pixelGlsl(const std::string& source, const std::string& profile = "ps_4_0") {
    fs::path dir = fs::temp_directory_path() / ("fxport-fxc-values-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::path file = dir / "shader.hlsl";
    std::ofstream(file) << source;
    CompileOptions o;
    o.useCache = false;
    return compileShaderFiles({{file.string(), "main", profile}}, o).shaders.at(0).glsl;
}

}  // namespace

// sm1-const-folding L104-L136: fxc folds unsuffixed int literals exactly and converts the result
// to int as x86 does, INT_MIN where it is out of range (a uint then reads 2^31); glslang wraps to
// 1705032704. A sum that stays in range is the same either way; u-suffixed literals wrap (L117).
TEST(FxcValues, OverflowingIntLiteralFoldIsIntMin) {
    for (const char* profile : {"ps_2_0", "ps_4_0"}) {
        const std::string glsl = pixelGlsl(
            "float4 main() : SV_TARGET\n{\n    int x = 3000000000 + 3000000000;\n"
            "    return float4(x, 3000000000 + 3000000000, 3000000000u + 3000000000u, 1000 + 2000);\n}\n",
            profile);
        EXPECT_NE(glsl.find("vec4(-2147483648.0, -2147483648.0, 1705032704.0, 3000.0)"), std::string::npos) << profile << "\n" << glsl;
    }
    // SM 4: INT_MIN read as a uint (SM 1-3 refuse the uint: negative_uint_constants).
    const std::string glsl = pixelGlsl("float4 main() : SV_TARGET\n{\n    uint y = 3000000000 + 3000000000;\n    return y;\n}\n");
    EXPECT_NE(glsl.find("vec4(2147483648.0)"), std::string::npos) << glsl;
}

// lhs-cast L88, L102: a cast in parentheses with a swizzle after it writes the components the
// swizzles reach, the value converted by the outermost cast (SM 2-3); SM 4 refuses both (the
// casts change the component type).
TEST(FxcValues, ParenthesisedLvalueCastWritesTheSwizzledComponents) {
    EXPECT_NE(pixelGlsl("float4 main() : sv_target\n{\n    float4 f = 0;\n    ((int4) f).xy = float2(1.4, 3.8);\n    return f;\n}\n", "ps_2_0")
                  .find("vec4(1.0, 3.0, 0.0, 0.0)"),
              std::string::npos);
    const std::string nested = "float4 main() : sv_target\n{\n    float4 f = 0;\n    ((float3)((int4) f).xyz).zx = float2(1.5, 2.5);\n    return f;\n}\n";
    EXPECT_NE(pixelGlsl(nested, "ps_2_0").find("vec4(2.5, 0.0, 1.5, 0.0)"), std::string::npos) << pixelGlsl(nested, "ps_2_0");
    EXPECT_THROW(pixelGlsl(nested, "ps_4_0"), CompileError);
}

// unroll L25: `[unroll(n)]` is the most iterations the loop runs (fxc emits n copies of the body),
// so the loop to 8 stops at 4 (the suite's probe). glslang does not fold the loops, so the GLSL is
// read for the limit ahead of each loop's own condition: a `for`, a limit above the trip count, a
// `while`, and a loop without a condition as the unbraced body of an `if`.
TEST(FxcValues, UnrollCountCapsTheIterations) {
    const std::string glsl = pixelGlsl(
        "float4 main() : sv_target\n{\n    int i, j = 0, k = 0, n = 0;\n    [unroll(4)]\n    for (i = 0; i < 8; ++i);\n"
        "    [unroll(20)] for (j = 0; j < 8; ++j) {}\n    [unroll(3)] while (k < 10) ++k;\n"
        "    if (i > 0) [allow_uav_condition] [unroll(2)] for (;;) ++n;\n    return float4(i, j, k, n);\n}\n");
    for (const char* limit : {" < 4u) && (", " < 20u) && (", " < 3u) && (", " < 2u; )"})
        EXPECT_NE(glsl.find(limit), std::string::npos) << limit << "\n" << glsl;
}

// srv-buffers L95: a Buffer's Load takes an int location; fxc converts a vector argument to it by
// keeping the first component (element 2 of float2(2, 9999)), a matrix its _m00.
TEST(FxcValues, BufferLoadOfAVectorReadsItsFirstComponent) {
    const std::string glsl = pixelGlsl(
        "Buffer b;\nBuffer<uint> u;\nfloat4 main() : sv_target\n{\n    float2x2 m = {5, 6, 7, 8};\n"
        "    return b.Load(float2(2, 9999)) + u.Load(m);\n}\n");
    EXPECT_NE(glsl.find("texelFetch(b, 2)"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("texelFetch(u, 5)"), std::string::npos) << glsl;
}

// minimum-precision L5: a flat initializer of a min-precision matrix (`min16uint4x2 e = {14.4, ...}`,
// the values truncated) and mul of an integer matrix, which fxc computes in the common component
// type and glslang has no overload for: rows (14 15)(16 17)(18 19)(20 21) times (4, 5), and the
// int2x2 product (1 2)(3 4) x (5 6)(7 8) = (19 22)(43 50).
TEST(FxcValues, IntegerMatrixProducts) {
    std::string glsl = pixelGlsl(
        "float4 main() : sv_target\n{\n    min10float2 b = {4, 5};\n    min16uint4x2 e = {14.4, 15, 16, 17, 18, 19, 20, 21};\n"
        "    return mul(e, b);\n}\n");
    EXPECT_NE(glsl.find("vec4(131.0, 149.0, 167.0, 185.0)"), std::string::npos) << glsl;
    glsl = pixelGlsl("float4 main() : sv_target\n{\n    int2x2 e = {1, 2, 3, 4};\n    int2x2 f = {5, 6, 7, 8};\n    int2x2 r = mul(e, f);\n"
                     "    return float4(r[0], r[1]);\n}\n");
    EXPECT_NE(glsl.find("vec4(19.0, 22.0, 43.0, 50.0)"), std::string::npos) << glsl;
}

// uav-out-param L40: an inout argument that is an element of a typed UAV is read before the call
// (0.1 + 0.1 = 0.2 on D3D); glslang passes an undefined value in and only writes the result back.
// The translation must load each element it passes inout (imageLoad), a swizzled one too
// (all its components: fxc refuses a partial write of a typed UAV element, uav-rwtexture L13).
TEST(FxcValues, InoutUavElementArgumentIsReadBeforeTheCall) {
    const std::string glsl = pixelGlsl(
        "RWTexture2D<float> u;\nRWBuffer<float2> b;\nvoid add(inout float f) { f += 0.1; }\n"
        "void scale(inout float2 v, float s) { v *= s; }\n"
        "[numthreads(1, 1, 1)]\nvoid main(uint3 id : SV_DispatchThreadID)\n{\n    add(u[id.xy]);\n    scale(b[id.x].yx, 2);\n}\n",
        "cs_5_0");
    EXPECT_NE(glsl.find("imageLoad(u, "), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("imageLoad(b, "), std::string::npos) << glsl;
    EXPECT_EQ(glsl.find("writeonly"), std::string::npos) << glsl;
}

// combined-samplers L148: a global texture array of two dimensions (xlate/src/rewrite/
// object_array_dimensions.h) is one array of four on consecutive registers, the last index running
// fastest, so tex[0][1] is element 1 and tex[1][1] element 3; glslang alone found no texture behind
// `tex[1][1].Sample` ("unable to find texture symbol").
TEST(FxcValues, TwoDimensionalTextureArraysAreFlattenedRowByRow) {
    const std::string glsl = pixelGlsl("Texture2D tex[2][2];\nsampler sam;\nfloat4 main() : sv_target\n{\n"
                                       "    return 100 * tex[0][1].Load(int3(0, 0, 0)) + tex[1][1].Sample(sam, float2(0, 0));\n}\n");
    EXPECT_NE(glsl.find("sampler2D fxport_tex_SPIRV_Cross_DummySampler[4]"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("texelFetch(fxport_tex_SPIRV_Cross_DummySampler[1]"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("texture(fxport_tex_sam[3]"), std::string::npos) << glsl;
}

// initializer-objects L16: a local array of textures initialized from globals, read by literal
// indices (xlate/src/rewrite/local_object_arrays.h): each element is its texture, as fxc resolves
// it; glslang alone wrote a module with an id defined twice.
TEST(FxcValues, LocalTextureArrayElementsAreTheirTextures) {
    const std::string glsl = pixelGlsl("Texture2D tex1;\nTexture2D tex2;\nfloat4 main() : sv_target\n{\n"
                                       "    Texture2D q[2] = {tex1, tex2};\n    return q[0].Load(int3(0, 0, 0)) + 2 * q[1].Load(int3(0, 0, 0));\n}\n");
    EXPECT_NE(glsl.find("texelFetch(fxport_tex1"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("(texelFetch(fxport_tex2_SPIRV_Cross_DummySampler, ivec2(0), 0) * 2.0)"), std::string::npos) << glsl;
}
