// One small headless render per row of the D3D-on-GL contract (docs/DESIGN.md, ARCHITECTURE.md),
// checked pixel by pixel against values computed here from the D3D rules.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "opaque_draw_test.h"
#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::drawQuad;
using test::readFloats;
using test::runtimeFixture;
using test::testDevice;

class Conventions : public test::OpaqueDrawTest {
protected:
    Effect& effect() {
        static Effect e(testDevice(), runtimeFixture("Conventions.fx"));
        return e;
    }
    void use(const std::string& technique) {
        effect().CurrentTechnique = effect().Techniques[technique];
        effect().CurrentTechnique->Passes[0].Apply();
    }
};

// Row "NDC z in [0,1]; texture v=0 is the top row" + row "D3D9 pixel centres": a full-screen quad
// with UV 0..1 gives pixel (i,j) the UV (i/W, j/H) under vs_3_0, and the top-left texel of the
// target is what NDC (-1,+1) drew.
TEST_F(Conventions, HalfPixelAndOrientationUnderShaderModel3) {
    const int W = 8, H = 4;
    RenderTarget2D target(device, W, H, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.Clear(Color::Black);
    use("UV");
    drawQuad(device);
    std::vector<float> px = readFloats(target);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const float* p = &px[std::size_t(y * W + x) * 4];
            // fxport places D3D9 geometry 1/256 pixel short of the half-pixel shift (see
            // state_apply.cpp): the UV is biased by at most that much, never below D3D's.
            EXPECT_NEAR(p[0], float(x) / W, 1.0 / (256 * W) + 1e-6) << "pixel " << x << "," << y;
            EXPECT_NEAR(p[1], float(y) / H, 1.0 / (256 * H) + 1e-6) << "pixel " << x << "," << y;
            EXPECT_GE(p[0], float(x) / W) << "pixel " << x << "," << y;
            EXPECT_GE(p[1], float(y) / H) << "pixel " << x << "," << y;
        }
}

TEST_F(Conventions, NoHalfPixelShiftUnderShaderModel4) {
    const int W = 8, H = 4;
    Effect sm4(device, runtimeFixture("ConventionsSM4.fx"));
    RenderTarget2D target(device, W, H, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.Clear(Color::Black);
    sm4.CurrentTechnique->Passes[0].Apply();
    drawQuad(device);
    std::vector<float> px = readFloats(target);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const float* p = &px[std::size_t(y * W + x) * 4];
            EXPECT_NEAR(p[0], (x + 0.5f) / W, 1e-5) << "pixel " << x << "," << y;
            EXPECT_NEAR(p[1], (y + 0.5f) / H, 1e-5) << "pixel " << x << "," << y;
        }
}

// A quad drawn only over NDC x<0, y>0 lands in the top-left quarter of the target's memory.
TEST_F(Conventions, TopLeftOfNdcIsFirstRowOfTarget) {
    RenderTarget2D target(device, 4, 4, false, SurfaceFormat::Color);
    device.SetRenderTarget(target);
    device.Clear(Color::Black);
    effect().Parameters["Color"].SetValue(Vector4(1, 0, 0, 1));
    use("SolidColor");
    VertexPositionTexture v[6] = {{Vector3(-1, 1, 0), Vector2(0, 0)}, {Vector3(0, 1, 0), Vector2(0, 0)},
                                  {Vector3(-1, 0, 0), Vector2(0, 0)}, {Vector3(-1, 0, 0), Vector2(0, 0)},
                                  {Vector3(0, 1, 0), Vector2(0, 0)},  {Vector3(0, 0, 0), Vector2(0, 0)}};
    device.DrawUserPrimitives(PrimitiveType::TriangleList, v, 0, 2);
    std::vector<Color> px(16);
    target.GetData(px.data(), px.size());
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x)
            EXPECT_EQ(px[std::size_t(y * 4 + x)].R, (x < 2 && y < 2) ? 255 : 0) << "pixel " << x << "," << y;
}

// Row "NDC z in [0,1]": z = -0.25 is outside D3D's clip volume (GL's default would keep it), and
// depth tests see z directly.
TEST_F(Conventions, DepthRangeIsZeroToOne) {
    RenderTarget2D target(device, 4, 4, false, SurfaceFormat::Color, DepthFormat::Depth24);
    device.SetRenderTarget(target);
    device.Clear(ClearOptions::Target | ClearOptions::DepthBuffer, Color::Black, 1.0f, 0);
    device.DepthStencilState = DepthStencilState::Default;
    auto draw = [&](float z, Vector4 color) {
        effect().Parameters["Color"].SetValue(color);
        use("SolidColor");
        drawQuad(device, z);
    };
    draw(0.5f, Vector4(1, 0, 0, 1));
    draw(-0.25f, Vector4(0, 1, 0, 1));  // clipped: z < 0
    std::vector<Color> px(16);
    target.GetData(px.data(), px.size());
    EXPECT_EQ(px[5], Color(255, 0, 0, 255));
    draw(0.75f, Vector4(0, 1, 0, 1));   // behind 0.5: fails LessEqual
    target.GetData(px.data(), px.size());
    EXPECT_EQ(px[5], Color(255, 0, 0, 255));
    draw(0.25f, Vector4(0, 0, 1, 1));   // in front
    target.GetData(px.data(), px.size());
    EXPECT_EQ(px[5], Color(0, 0, 255, 255));
}

// Row "DepthRead": tests without writing.
TEST_F(Conventions, DepthReadTestsButDoesNotWrite) {
    RenderTarget2D target(device, 4, 4, false, SurfaceFormat::Color, DepthFormat::Depth24);
    device.SetRenderTarget(target);
    device.Clear(ClearOptions::Target | ClearOptions::DepthBuffer, Color::Black, 1.0f, 0);
    auto draw = [&](float z, Vector4 color, const DepthStencilState& state) {
        device.DepthStencilState = state;
        effect().Parameters["Color"].SetValue(color);
        use("SolidColor");
        drawQuad(device, z);
    };
    draw(0.5f, Vector4(1, 0, 0, 1), DepthStencilState::Default);
    draw(0.25f, Vector4(0, 1, 0, 1), DepthStencilState::DepthRead);  // passes, must not write 0.25
    draw(0.6f, Vector4(1, 1, 1, 1), DepthStencilState::DepthRead);   // fails against 0.5
    std::vector<Color> px(16);
    target.GetData(px.data(), px.size());
    EXPECT_EQ(px[5], Color(0, 255, 0, 255));
    draw(0.4f, Vector4(0, 0, 1, 1), DepthStencilState::Default);  // passes only if 0.25 was not written
    target.GetData(px.data(), px.size());
    EXPECT_EQ(px[5], Color(0, 0, 255, 255));
}

// Row "mul(v, M)": HLSL sees M[r][c] == XNA M(r+1)(c+1), column_major and row_major alike.
TEST_F(Conventions, MulMatchesXnaVector4Transform) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> u(-2, 2);
    RenderTarget2D target(device, 1, 1, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    for (const char* technique : {"Mul", "MulRowMajor"}) {
        for (int trial = 0; trial < 4; ++trial) {
            Matrix m;
            for (int i = 0; i < 16; ++i) m.data()[i] = u(rng);
            Vector4 v(u(rng), u(rng), u(rng), u(rng));
            effect().Parameters[std::string(technique) == "Mul" ? "Transform" : "TransformRowMajor"].SetValue(m);
            effect().Parameters["Vector"].SetValue(v);
            use(technique);
            drawQuad(device);
            std::vector<float> px = readFloats(target);
            Vector4 expected = Vector4::Transform(v, m);
            EXPECT_NEAR(px[0], expected.X, 1e-5) << technique;
            EXPECT_NEAR(px[1], expected.Y, 1e-5) << technique;
            EXPECT_NEAR(px[2], expected.Z, 1e-5) << technique;
            EXPECT_NEAR(px[3], expected.W, 1e-5) << technique;
        }
    }
}

// Row "culling": a triangle clockwise in the final image is kept by CullCounterClockwise (XNA's
// default) and removed by CullClockwise.
TEST_F(Conventions, CullModesFollowWindingAsSeen) {
    RenderTarget2D target(device, 4, 4, false, SurfaceFormat::Color);
    device.SetRenderTarget(target);
    effect().Parameters["Color"].SetValue(Vector4(1, 1, 1, 1));
    // Top-left, top-right, bottom-left on screen: clockwise as seen.
    VertexPositionTexture clockwise[3] = {{Vector3(-1, 1, 0), Vector2()}, {Vector3(3, 1, 0), Vector2()},
                                          {Vector3(-1, -3, 0), Vector2()}};
    VertexPositionTexture counter[3] = {clockwise[0], clockwise[2], clockwise[1]};
    struct Case {
        const RasterizerState* state;
        VertexPositionTexture* tri;
        bool drawn;
    } cases[] = {{&RasterizerState::CullCounterClockwise, clockwise, true},
                 {&RasterizerState::CullCounterClockwise, counter, false},
                 {&RasterizerState::CullClockwise, clockwise, false},
                 {&RasterizerState::CullClockwise, counter, true},
                 {&RasterizerState::CullNone, counter, true}};
    for (const Case& c : cases) {
        device.Clear(Color::Black);
        device.RasterizerState = *c.state;
        use("SolidColor");
        device.DrawUserPrimitives(PrimitiveType::TriangleList, c.tri, 0, 1);
        std::vector<Color> px(16);
        target.GetData(px.data(), px.size());
        EXPECT_EQ(px[5].R, c.drawn ? 255 : 0) << "cull mode " << int(c.state->CullMode) << (c.tri == clockwise ? " clockwise" : " counter-clockwise");
    }
}

// Row "sampler_state applied at Apply(); device sampler states set after Apply() win".
TEST_F(Conventions, DeviceSamplerStateAfterApplyWins) {
    Texture2D tex(device, 2, 1, false, SurfaceFormat::Vector4);
    const float texels[8] = {0, 0, 0, 1, 1, 1, 1, 1};
    tex.SetData(texels, 8);
    effect().Parameters["Tex"].SetValue(tex);
    RenderTarget2D target(device, 8, 1, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);

    device.SamplerStates[0] = SamplerState::LinearClamp;  // before Apply: the effect's Point wins
    use("Sample");
    EXPECT_EQ(device.SamplerStates[0].Filter, TextureFilter::Point);
    drawQuad(device);
    std::vector<float> point = readFloats(target);

    use("Sample");
    device.SamplerStates[0] = SamplerState::LinearClamp;  // after Apply: the device wins
    drawQuad(device);
    std::vector<float> linear = readFloats(target);
    // Pixel x samples u = x/8 (D3D9 centres). Point: texel floor(u*2); linear: clamp(u*2-0.5, 0, 1).
    for (int x = 0; x < 8; ++x) {
        float u = x / 8.0f;
        EXPECT_NEAR(point[std::size_t(x) * 4], std::floor(u * 2) >= 1 ? 1.0f : 0.0f, 1e-6) << x;
        EXPECT_NEAR(linear[std::size_t(x) * 4], std::clamp(u * 2 - 0.5f, 0.0f, 1.0f), 1.0f / 256) << x;
    }
}

// Row "MRT up to 4".
TEST_F(Conventions, MultipleRenderTargets) {
    RenderTarget2D t0(device, 4, 2, false, SurfaceFormat::Color), t1(device, 4, 2, false, SurfaceFormat::Color),
        t2(device, 4, 2, false, SurfaceFormat::Color), t3(device, 4, 2, false, SurfaceFormat::Vector4);
    device.SetRenderTargets({t0, t1, t2, t3});
    device.Clear(Color::Black);
    use("MRT");
    drawQuad(device);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    std::vector<float> p0 = readFloats(t0), p1 = readFloats(t1), p2 = readFloats(t2), p3 = readFloats(t3);
    for (int i = 0; i < 8; ++i) {
        std::size_t k = std::size_t(i) * 4;
        EXPECT_EQ(p0[k], 1.0f);
        EXPECT_EQ(p1[k + 1], 1.0f);
        EXPECT_EQ(p2[k + 2], 1.0f);
        EXPECT_NEAR(p3[k + 0], (i % 4) / 4.0f, 1.0 / (256 * 4) + 1e-6);  // D3D9 centres, 1/256 px bias
        EXPECT_NEAR(p3[k + 1], (i / 4) / 2.0f, 1.0 / (256 * 2) + 1e-6);
        EXPECT_NEAR(p3[k + 2], 0.5f, 1e-6);
    }
}

// D3D9 (oC# not written: "the corresponding render target must not be updated at all"), and D3D10+
// alike: a target the pixel shader has no output for keeps its contents. GL leaves it undefined, so
// draws mask it (ColorPS writes COLOR0 only; target 1 keeps its clear colour, not a zero).
TEST_F(Conventions, TargetsThePixelShaderDoesNotWriteKeepTheirContents) {
    RenderTarget2D t0(device, 4, 2, false, SurfaceFormat::Vector4), t1(device, 4, 2, false, SurfaceFormat::Vector4);
    device.SetRenderTargets({t0, t1});
    device.Clear(Color(64, 128, 192, 255));
    effect().Parameters["Color"].SetValue(Vector4(1, 0.5f, 0.25f, 1));
    use("SolidColor");
    drawQuad(device);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    std::vector<float> p0 = readFloats(t0), p1 = readFloats(t1);
    const float written[4] = {1, 0.5f, 0.25f, 1}, cleared[4] = {64 / 255.0f, 128 / 255.0f, 192 / 255.0f, 1};
    for (std::size_t i = 0; i < p0.size(); ++i) {
        EXPECT_EQ(p0[i], written[i % 4]) << "target 0 value " << i;
        EXPECT_FLOAT_EQ(p1[i], cleared[i % 4]) << "target 1 value " << i;
    }
}

// Row "cube faces in XNA CubeMapFace order": each face cleared to its own colour, sampled back by
// direction; and a quad in a face's top-left quarter is found in the D3D direction for it.
TEST_F(Conventions, CubeFacesByDirection) {
    // PreserveContents: each face is set twice (cleared, then drawn into).
    RenderTargetCube cube(device, 4, false, SurfaceFormat::Color, DepthFormat::None, 0, RenderTargetUsage::PreserveContents);
    const Color colors[6] = {Color(255, 0, 0), Color(0, 255, 0), Color(0, 0, 255),
                             Color(255, 255, 0), Color(0, 255, 255), Color(255, 0, 255)};
    for (int f = 0; f < 6; ++f) {
        device.SetRenderTarget(cube, CubeMapFace(f));
        device.Clear(colors[f]);
    }
    // Top-left quarter of +X drawn white.
    device.SetRenderTarget(cube, CubeMapFace::PositiveX);
    effect().Parameters["Color"].SetValue(Vector4(1, 1, 1, 1));
    use("SolidColor");
    VertexPositionTexture quarter[6] = {{Vector3(-1, 1, 0), Vector2()}, {Vector3(0, 1, 0), Vector2()},
                                        {Vector3(-1, 0, 0), Vector2()}, {Vector3(-1, 0, 0), Vector2()},
                                        {Vector3(0, 1, 0), Vector2()},  {Vector3(0, 0, 0), Vector2()}};
    device.DrawUserPrimitives(PrimitiveType::TriangleList, quarter, 0, 2);

    RenderTarget2D target(device, 1, 1, false, SurfaceFormat::Color);
    device.SetRenderTarget(target);
    effect().Parameters["CubeTex"].SetValue(cube);
    auto sample = [&](Vector3 direction) {
        effect().Parameters["Direction"].SetValue(Vector4(direction, 0));
        use("Cube");
        drawQuad(device);
        std::vector<Color> px(1);
        target.GetData(px.data(), 1);
        return px[0];
    };
    const Vector3 directions[6] = {Vector3(1, 0.1f, -0.2f), Vector3(-1, 0.1f, 0.2f), Vector3(0.1f, 1, 0.2f),
                                   Vector3(0.1f, -1, 0.2f), Vector3(0.1f, 0.2f, 1), Vector3(-0.1f, 0.2f, -1)};
    for (int f = 0; f < 6; ++f) EXPECT_EQ(sample(directions[f]), colors[f]) << "face " << f;
    // D3D +X face: u = (-z/x + 1)/2, v = (-y/x + 1)/2; top-left quarter = z > 0, y > 0.
    EXPECT_EQ(sample(Vector3(1, 0.5f, 0.5f)), Color(255, 255, 255)) << "+X top-left";
    EXPECT_EQ(sample(Vector3(1, -0.5f, 0.5f)), colors[0]) << "+X bottom-left";
    EXPECT_EQ(sample(Vector3(1, 0.5f, -0.5f)), colors[0]) << "+X top-right";
}

// Row "Blend functions incl. Min": as a pass state (D3D9 BlendOp = Min) and additive via the
// device's BlendState.
TEST_F(Conventions, MinAndAdditiveBlending) {
    RenderTarget2D target(device, 2, 2, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.Clear(ClearOptions::Target, Vector4(0.5f, 0.5f, 0.5f, 0.5f), 1, 0);
    effect().Parameters["Color"].SetValue(Vector4(0.25f, 0.75f, 0.5f, 1));
    use("MinBlend");
    drawQuad(device);
    std::vector<float> px = readFloats(target);
    EXPECT_FLOAT_EQ(px[0], 0.25f);
    EXPECT_FLOAT_EQ(px[1], 0.5f);
    EXPECT_FLOAT_EQ(px[2], 0.5f);
    EXPECT_FLOAT_EQ(px[3], 0.5f);

    device.Clear(ClearOptions::Target, Vector4(0.25f, 0.25f, 0.25f, 0.25f), 1, 0);
    effect().Parameters["Color"].SetValue(Vector4(0.5f, 0.25f, 1.0f, 0.5f));
    use("SolidColor");
    device.BlendState = BlendState::Additive;  // src * srcAlpha + dst
    drawQuad(device);
    px = readFloats(target);
    EXPECT_FLOAT_EQ(px[0], 0.25f + 0.5f * 0.5f);
    EXPECT_FLOAT_EQ(px[1], 0.25f + 0.25f * 0.5f);
    EXPECT_FLOAT_EQ(px[2], 0.25f + 1.0f * 0.5f);
    EXPECT_FLOAT_EQ(px[3], 0.25f + 0.5f * 0.5f);
}

// The seed's FullscreenQuad (indexed, clockwise) is kept by default culling and gives pixel
// (i,j) the D3D9 UV (i/W, j/H): the reason the tutorial adds halfPixel.
TEST_F(Conventions, FullscreenQuadLikeTheTutorial) {
    const int W = 6, H = 3;
    RenderTarget2D target(device, W, H, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.Clear(Color::Black);
    device.RasterizerState = RasterizerState::CullCounterClockwise;
    FullscreenQuad quad(device);
    use("UV");
    quad.Draw(device);
    std::vector<float> px = readFloats(target);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const float* p = &px[std::size_t(y * W + x) * 4];
            EXPECT_NEAR(p[0], float(x) / W, 1.0 / (256 * W) + 1e-6) << x << "," << y;
            EXPECT_NEAR(p[1], float(y) / H, 1.0 / (256 * H) + 1e-6) << x << "," << y;
            EXPECT_EQ(p[3], 1.0f) << x << "," << y;
        }
}

// Row "effect parameter defaults": Color = float4(1,1,1,1) in the source.
TEST_F(Conventions, ParameterDefaultsFromSource) {
    Effect fresh(device, runtimeFixture("Conventions.fx"));
    Vector4 c = fresh.Parameters["Color"].GetValueVector4();
    EXPECT_EQ(c, Vector4(1, 1, 1, 1));
}

}  // namespace
}  // namespace fxport
