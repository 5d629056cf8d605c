// FiniteCheck (runtime/graphics/include/fxport/graphics/finite_check.h): a pass that leaves NaN/Inf
// in a float or half target, or in one face of a cube target, is caught and named with its pass,
// target, pixel, channel and value; a clean pass is not; targets the pass did not bind are not
// blamed on it. The effect writes a value set by the test into exactly one pixel (VPOS).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include <unistd.h>

#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::drawQuad;
using test::testDevice;

// Writes `Value` at pixel (5, 3) and `Background` everywhere else.
const char* kOnePixelEffect = R"(
float4 Value;
float4 Background;
struct VSO { float4 Position : POSITION0; float2 UV : TEXCOORD0; };
VSO VS(float4 p : POSITION0, float2 uv : TEXCOORD0) { VSO o; o.Position = p; o.UV = uv; return o; }
float4 PS(float2 pos : VPOS) : COLOR0 { return (pos.x == 5 && pos.y == 3) ? Value : Background; }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";

Effect& onePixelEffect() {
    static std::unique_ptr<Effect> effect = [] {
        // One file per process: ctest runs each test case as its own process, in parallel, and a
        // shared name let one process read the file while another was rewriting it.
        const auto path = std::filesystem::temp_directory_path() /
                          ("fxport_finite_check_one_pixel_" + std::to_string(::getpid()) + ".fx");
        std::ofstream(path) << kOnePixelEffect;
        return std::make_unique<Effect>(testDevice(), path.string());
    }();
    return *effect;
}

void drawOnePixel(GraphicsDevice& device, Vector4 value) {
    Effect& effect = onePixelEffect();
    effect.Parameters["Value"].SetValue(value);
    effect.Parameters["Background"].SetValue(Vector4(0.25f, 0.5f, 0.75f, 1.0f));
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::None;
    device.RasterizerState = RasterizerState::CullNone;
    effect.CurrentTechnique->Passes[0].Apply();
    drawQuad(device);
}

const float kNaN = std::numeric_limits<float>::quiet_NaN();

TEST(FiniteCheck, NaNInAHalfFloatTargetIsNamedWithPassTargetPixelAndChannel) {
    GraphicsDevice& device = testDevice();
    RenderTarget2D half(device, 8, 8, false, SurfaceFormat::HalfVector4);
    half.Name = "HalfTarget";
    FiniteCheck check(device);
    check.beginPass("WritesNaN");
    device.SetRenderTarget(half);
    drawOnePixel(device, Vector4(1, kNaN, 1, 1));
    device.SetRenderTarget(nullptr);
    std::vector<NonFiniteTarget> found = check.endPass();
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].pass, "WritesNaN");
    EXPECT_EQ(found[0].target, "HalfTarget");
    EXPECT_EQ(found[0].face, -1);
    EXPECT_EQ(found[0].x, 5);
    EXPECT_EQ(found[0].y, 3);
    EXPECT_EQ(found[0].channel, 1);
    EXPECT_TRUE(std::isnan(found[0].value));
    EXPECT_EQ(found[0].count, 1);
    EXPECT_EQ(check.findings().size(), 1u);
    EXPECT_NE(found[0].describe().find("pass 'WritesNaN' wrote NaN into 'HalfTarget' at pixel (5, 3) channel g"),
              std::string::npos)
        << found[0].describe();
}

// Infinity itself (a float32 overflow upstream). Note: a finite float beyond half range (1e6) is
// stored as +Inf by some drivers and saturated to 65504 by llvmpipe: that is measured by fxdemo
// stability, not pinned here.
TEST(FiniteCheck, InfInAHalfTargetIsCaught) {
    GraphicsDevice& device = testDevice();
    RenderTarget2D half(device, 8, 8, false, SurfaceFormat::HalfSingle);
    FiniteCheck check(device);
    check.beginPass("Overflow");
    device.SetRenderTarget(half);
    drawOnePixel(device, Vector4(-std::numeric_limits<float>::infinity(), 0, 0, 1));
    std::vector<NonFiniteTarget> found = check.endPass();
    device.SetRenderTarget(nullptr);
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].channel, 0);
    EXPECT_TRUE(std::isinf(found[0].value) && found[0].value < 0);
    EXPECT_EQ(found[0].x, 5);
    EXPECT_EQ(found[0].y, 3);
    EXPECT_NE(found[0].describe().find("wrote -Inf"), std::string::npos);
    // Unnamed targets are described by type, size and format.
    EXPECT_EQ(found[0].target, "unnamed RenderTarget2D (8x8 HalfSingle)");
}

TEST(FiniteCheck, NaNInOneCubeFaceNamesTheFace) {
    GraphicsDevice& device = testDevice();
    RenderTargetCube cube(device, 8, false, SurfaceFormat::Single);
    cube.Name = "ShadowCube";
    FiniteCheck check(device);
    check.beginPass("CubeFaces");
    device.SetRenderTarget(cube, CubeMapFace::PositiveX);
    drawOnePixel(device, Vector4(2, 0, 0, 1));  // finite
    device.SetRenderTarget(cube, CubeMapFace::NegativeY);
    drawOnePixel(device, Vector4(kNaN, 0, 0, 1));
    device.SetRenderTarget(nullptr);
    std::vector<NonFiniteTarget> found = check.endPass();
    ASSERT_EQ(found.size(), 1u);
    EXPECT_EQ(found[0].target, "ShadowCube");
    EXPECT_EQ(found[0].face, int(CubeMapFace::NegativeY));
    EXPECT_EQ(found[0].x, 5);
    EXPECT_EQ(found[0].y, 3);
    EXPECT_TRUE(std::isnan(found[0].value));
    EXPECT_NE(found[0].describe().find("of cube face 3"), std::string::npos);
    // +X, -Y and the back buffer (Color: skipped, it cannot hold NaN) were bound.
    EXPECT_EQ(check.targetsScanned(), 2);
    EXPECT_GE(check.targetsSkipped(), 1);
}

TEST(FiniteCheck, CleanPassIsNotReported) {
    GraphicsDevice& device = testDevice();
    RenderTarget2D full(device, 8, 8, false, SurfaceFormat::Vector4);
    RenderTarget2D half(device, 8, 8, false, SurfaceFormat::HalfVector4);
    FiniteCheck check(device);
    check.beginPass("Clean");
    // One at a time: a second MRT target the pixel shader writes no colour to holds undefined
    // values afterwards (llvmpipe: NaN), which the check would rightly report.
    device.SetRenderTarget(full);
    drawOnePixel(device, Vector4(-3.0e38f, 65000.0f, 0, 1));  // large but finite
    device.SetRenderTarget(half);
    drawOnePixel(device, Vector4(-60000.0f, 65000.0f, 0, 1));  // finite in half too
    device.SetRenderTarget(nullptr);
    for (const NonFiniteTarget& f : check.endPass()) ADD_FAILURE() << f.describe();
    EXPECT_TRUE(check.findings().empty());
    EXPECT_EQ(check.targetsScanned(), 2);
}

TEST(FiniteCheck, TargetsThePassDidNotBindAreNotBlamedOnIt) {
    GraphicsDevice& device = testDevice();
    RenderTarget2D broken(device, 8, 8, false, SurfaceFormat::Vector4);
    RenderTarget2D other(device, 8, 8, false, SurfaceFormat::Vector4);
    broken.Name = "Broken";
    FiniteCheck check(device);
    check.beginPass("Breaks");
    device.SetRenderTarget(broken);
    drawOnePixel(device, Vector4(kNaN, 0, 0, 1));
    EXPECT_EQ(check.endPass().size(), 1u);
    // The target is still bound when the next pass begins: a pass that binds it (even only at its
    // start) is answerable for it, so this one switches away first.
    device.SetRenderTarget(other);
    check.beginPass("Later");
    drawOnePixel(device, Vector4(1, 1, 1, 1));
    device.SetRenderTarget(nullptr);
    EXPECT_TRUE(check.endPass().empty());
    ASSERT_EQ(check.findings().size(), 1u);
    EXPECT_EQ(check.findings()[0].pass, "Breaks");
}

TEST(FiniteCheck, DisposedTargetsDropOutOfTheList) {
    GraphicsDevice& device = testDevice();
    FiniteCheck check(device);
    check.beginPass("Dispose");
    {
        RenderTarget2D temporary(device, 8, 8, false, SurfaceFormat::Vector4);
        device.SetRenderTarget(temporary);
        drawOnePixel(device, Vector4(kNaN, 0, 0, 1));
    }
    for (const RenderTargetBinding& b : device.targetsBoundSinceMark()) EXPECT_FALSE(b.RenderTarget->IsDisposed());
    EXPECT_TRUE(check.endPass().empty());
}

TEST(FiniteCheck, FindNonFiniteScansOnlyTheFormatsChannels) {
    // A one-channel format reads back as (r, 0, 0, 1): only r counts.
    const float texels[8] = {1, kNaN, kNaN, kNaN, 2, 0, 0, std::numeric_limits<float>::infinity()};
    NonFiniteTarget found;
    EXPECT_FALSE(findNonFinite(texels, 2, 1, 1, found));
    EXPECT_TRUE(findNonFinite(texels, 2, 1, 4, found));
    EXPECT_EQ(found.x, 0);
    EXPECT_EQ(found.channel, 1);
    EXPECT_EQ(found.count, 2);
}

}  // namespace
}  // namespace fxport
