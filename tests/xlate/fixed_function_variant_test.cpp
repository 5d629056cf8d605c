// The GLSL variants of the D3D9 fixed-function stages (xlate/fixed_function.h) on shaders shaped as
// SPIRV-Cross writes them: what each step adds, and the shaders that cannot have a step (refused
// with the reason, never a variant that would draw something else). The pixels they draw are
// checked against the D3D9 formulas in tests/runtime/fixed_function_test.cpp.
#include <gtest/gtest.h>

#include "fxport/xlate/fixed_function.h"

namespace fxport::xlate {
namespace {

const char* const kPixel = R"(#version 450

layout(location = 0) in vec4 i0;
layout(location = 16) in vec4 i1;
layout(location = 24) in vec4 i2;
layout(location = 0) out vec4 _entryPointOutput_o0;

void main()
{
    _entryPointOutput_o0 = vec4(i0.xy, i1.x, i2.x);
}
)";

const char* const kVertex = R"(#version 450

out gl_PerVertex
{
    vec4 gl_Position;
};

layout(location = 0) in vec4 i0;
layout(location = 29) out vec4 _entryPointOutput_o1;

void main()
{
    gl_Position = i0;
    _entryPointOutput_o1 = vec4(i0.z, 0.0, 0.0, 0.0);
}
)";

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(FixedFunctionVariant, PixelStepsRunAfterTheShaderOnTargetZero) {
    PixelFixedFunction w;
    w.alphaTest = w.fog = w.pointSprite = w.flatColors = true;
    w.fogInput = {24, 0};
    std::string why;
    std::optional<std::string> v = pixelFixedFunctionVariant(kPixel, w, why);
    ASSERT_TRUE(v) << why;
    EXPECT_TRUE(has(*v, "void fxport_shaderMain()"));
    // Sprites: TEXCOORD0 (location 0) is no longer an input; D3D9's (0, 0) is the top-left corner.
    EXPECT_FALSE(has(*v, "layout(location = 0) in vec4 i0;"));
    EXPECT_TRUE(has(*v, "i0 = vec4(gl_PointCoord.x, 1.0 - gl_PointCoord.y, 0.0, 1.0);"));
    EXPECT_TRUE(has(*v, "layout(location = 16) flat in vec4 i1;"));  // COLOR0 flat
    EXPECT_TRUE(has(*v, "float f = i2.x;"));                         // the FOG input the shader declares
    EXPECT_TRUE(has(*v, "_entryPointOutput_o0.rgb = mix(fxport_FogColor.rgb, _entryPointOutput_o0.rgb, clamp(f, 0.0, 1.0));"));
    EXPECT_TRUE(has(*v, "float a = _entryPointOutput_o0.a;"));
    // The steps follow the shader's own main.
    EXPECT_LT(v->find("fxport_shaderMain();\n    {"), v->find("discard"));
}

TEST(FixedFunctionVariant, VertexFogFromAnInputTheShaderDoesNotReadIsDeclared) {
    PixelFixedFunction w;
    w.fog = true;
    w.fogInput = {17, 3};  // COLOR1.w
    std::string why;
    std::optional<std::string> v = pixelFixedFunctionVariant(kPixel, w, why);
    ASSERT_TRUE(v) << why;
    EXPECT_TRUE(has(*v, "layout(location = 17) in vec4 fxport_FogInput;"));
    EXPECT_TRUE(has(*v, "float f = fxport_FogInput.w;"));
    w.fogInput = {-1, 0};  // nothing written: D3D reads 0
    v = pixelFixedFunctionVariant(kPixel, w, why);
    ASSERT_TRUE(v);
    EXPECT_TRUE(has(*v, "float f = 0.0;"));
}

TEST(FixedFunctionVariant, FogAndAlphaTestNeedAColourOutput) {
    PixelFixedFunction w;
    w.fog = true;
    std::string why;
    EXPECT_FALSE(pixelFixedFunctionVariant("#version 450\nvoid main()\n{\n}\n", w, why));
    EXPECT_EQ(why, "the shader writes no float4 colour to render target 0");
}

TEST(FixedFunctionVariant, ClipPlanesUseThePositionTheShaderWrote) {
    VertexFixedFunction w;
    w.clipPlanes = 2;
    w.pointSizeLocation = 29;
    std::string why;
    std::optional<std::string> v = vertexFixedFunctionVariant(kVertex, w, why);
    ASSERT_TRUE(v) << why;
    EXPECT_TRUE(has(*v, "    vec4 gl_Position;\n    float gl_ClipDistance[2];\n    float gl_PointSize;") ||
                has(*v, "{\n    float gl_ClipDistance[2];\n    float gl_PointSize;\n    vec4 gl_Position;"));
    EXPECT_TRUE(has(*v, "vec4 fxport_clipPosition = gl_Position;"));
    EXPECT_TRUE(has(*v, "gl_ClipDistance[1] = dot(fxport_clipPosition, fxport_ClipPlanes[1]);"));
    EXPECT_FALSE(has(*v, "gl_ClipDistance[2] ="));
    EXPECT_TRUE(has(*v, "gl_PointSize = clamp(_entryPointOutput_o1.x, fxport_PointSize.y, fxport_PointSize.z);"));
}

TEST(FixedFunctionVariant, AShaderWritingClipDistancesKeepsItsOwn) {
    VertexFixedFunction w;
    w.clipPlanes = 1;
    std::string why;
    std::string own = kVertex;
    own.replace(own.find("vec4 gl_Position;"), 17, "vec4 gl_Position;\n    float gl_ClipDistance[1];");
    EXPECT_FALSE(vertexFixedFunctionVariant(own, w, why));
    EXPECT_EQ(why, "the vertex shader writes SV_ClipDistance itself");
}

}  // namespace
}  // namespace fxport::xlate
