// Pixel tests of the second wave of real-world constructs (issue 24): fixtures under
// tests/fixtures/realworld2/ drawn headless and compared with what fxc's semantics say, computed
// here in double precision.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>

#include "opaque_draw_test.h"
#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::drawQuad;
using test::readFloats;
using test::testDevice;

std::string fixture(const std::string& name) { return std::string(FXPORT_REALWORLD2_FIXTURES) + "/" + name; }

class RealWorld2Render : public test::OpaqueDrawTest {
protected:
    // Draws the current technique's first pass over a W×H float target and reads it back. A pass
    // without vertex shader (SpriteBatch-style) keeps the one of Conventions.fx, bound first.
    std::vector<float> draw(Effect& effect, int w, int h) {
        RenderTarget2D target(device, w, h, false, SurfaceFormat::Vector4);
        device.SetRenderTarget(target);
        device.Clear(Color::Black);
        static Effect vertex(device, test::runtimeFixture("Conventions.fx"));
        vertex.CurrentTechnique = vertex.Techniques["SolidColor"];
        vertex.CurrentTechnique->Passes[0].Apply();
        effect.CurrentTechnique->Passes[0].Apply();
        drawQuad(device);
        std::vector<float> px = readFloats(target);
        device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        return px;
    }
    void expectEvery(const std::vector<float>& px, const std::array<double, 4>& expected, const char* what) {
        for (size_t i = 0; i < px.size(); ++i) EXPECT_NEAR(px[i], expected[i % 4], 1e-5) << what << " value " << i;
    }
};

// A shader writing global uniforms works on its own copy, taken afresh at every run.
TEST_F(RealWorld2Render, AssignedUniformsAreTheShadersOwnCopy) {
    Effect effect(device, fixture("declarations/AssignedUniforms.fx"), noCache());
    effect.Parameters["Tint"].SetValue(Vector4(0.1f, 0.2f, 0.3f, 0.9f));
    effect.Parameters["Counter"].SetValue(0.5f);
    // Tint.a = 1; ++Counter; c = Tint * (Scale *= 2); c + Counter + Scale (+ Hidden(0) - 0.5 = 0).
    const double scale = 2 * 2.0, counter = 1.5;
    const std::array<double, 4> expected = {0.1 * scale + counter + scale, 0.2 * scale + counter + scale, 0.3 * scale + counter + scale,
                                            1.0 * scale + counter + scale};
    expectEvery(draw(effect, 2, 2), expected, "first draw");
    expectEvery(draw(effect, 2, 2), expected, "second draw (the parameters are unchanged)");
}

// A `for` header's variable lives on after its loop, as in fxc.
TEST_F(RealWorld2Render, LoopVariablesLiveInTheEnclosingScope) {
    Effect effect(device, fixture("declarations/LoopVariableScope.fx"), noCache());
    // s = (0,1,2,3); best = 3; then s[0] += s[3], s[1] += s[2] leaves k = 2, j = 1; the last loop
    // declares i again (the same i) and adds 1 twice: best = 5, i = 2. Sum(s = (3, 3, 2, 3), true):
    // 2 * 11, plus n = 4 after its loop.
    expectEvery(draw(effect, 2, 2), {5, 2, 3, 26}, "loop variables");
}

// `float4(a, b, c) = v` assigns a = v.xy, b = v.z, c = v.w.
TEST_F(RealWorld2Render, ConstructorTargetsAssignTheirParts) {
    Effect effect(device, fixture("declarations/ConstructorAssignment.fx"), noCache());
    effect.Parameters["Packed"].SetValue(Vector4(10, 20, 30, 40));
    effect.Parameters["Input"].SetValue(Vector4(0.1f, 0.2f, 0.3f, 0.4f));
    // v = Input.wzyx * 2 = (0.8, 0.6, 0.4, 0.2); else branch: r = (a.x, a.y, c, 0).
    expectEvery(draw(effect, 2, 2), {0.8 + 0.8, 0.6 + 0.6, 0.4 + 0.2, 0.2}, "else branch");
    effect.Parameters["Input"].SetValue(Vector4(3, 0.2f, 0.3f, 0.4f));
    // v = (0.8, 0.6, 0.4, 6); r = Packed.
    expectEvery(draw(effect, 2, 2), {0.8 + 10, 0.6 + 20, 0.4 + 30, 6 + 40}, "if branch");
}

// One sampler, a cube texture for one technique and a 2D texture for the other.
TEST_F(RealWorld2Render, ASamplerTakesTheDimensionEachShaderGivesIt) {
    Effect effect(device, fixture("declarations/SamplerTwoDimensions.fx"), noCache());
    TextureCube cube(device, 1, false, SurfaceFormat::Color);
    const std::array<Color, 6> faces = {Color(255, 0, 0, 255), Color(0, 255, 0, 255), Color(0, 0, 255, 255),
                                        Color(255, 255, 0, 255), Color(0, 255, 255, 255), Color(255, 0, 255, 255)};
    for (int f = 0; f < 6; ++f) cube.SetData(static_cast<CubeMapFace>(f), &faces[size_t(f)], 1);
    effect.Parameters["LightTexture"].SetValue(cube);
    effect.Parameters["Direction"].SetValue(Vector3(0, 1, 0));  // +Y: face 2
    effect.CurrentTechnique = effect.Techniques["Cube"];
    expectEvery(draw(effect, 2, 2), {0, 0, 1, 1}, "cube");
    Texture2D flat(device, 2, 2, false, SurfaceFormat::Color);
    std::vector<Color> texels = {Color(10, 20, 30, 40), Color(50, 60, 70, 80), Color(90, 100, 110, 120), Color(130, 140, 150, 160)};
    flat.SetData(texels);
    effect.Parameters["LightTexture"].SetValue(flat);
    effect.CurrentTechnique = effect.Techniques["Flat"];
    // (0.25, 0.75): texel (0, 1), point filtered.
    expectEvery(draw(effect, 2, 2), {90 / 255.0, 100 / 255.0, 110 / 255.0, 120 / 255.0}, "2D");
}

// MonoGame's template: overloads picked by their uniforms, a uniform left to the application.
TEST_F(RealWorld2Render, UniformEntryParametersWithoutValuesAreParameters) {
    Effect effect(device, fixture("monogame/PlatformTemplate.fx"), noCache());
    Texture2D tex(device, 1, 1, false, SurfaceFormat::Color);
    std::vector<Color> texel = {Color(51, 102, 153, 204)};
    tex.SetData(texel);
    effect.Parameters["SpriteTexture"].SetValue(tex);
    effect.Parameters["WorldViewProjection"].SetValue(Matrix::Identity);
    effect.Parameters["Gain"].SetValue(0.5f);
    const std::array<double, 4> c = {0.2, 0.4, 0.6, 0.8};
    effect.CurrentTechnique = effect.Techniques["Plain"];  // PS(input) -> PS(input, false, 1)
    expectEvery(draw(effect, 2, 2), c, "Plain");
    effect.CurrentTechnique = effect.Techniques["Inverted"];  // PS(input, true, 2)
    expectEvery(draw(effect, 2, 2), {1 - 2 * c[0], 1 - 2 * c[1], 1 - 2 * c[2], 1 - 2 * c[3]}, "Inverted");
    effect.CurrentTechnique = effect.Techniques["Tunable"];  // PS(input, true, Gain)
    expectEvery(draw(effect, 2, 2), {1 - 0.5 * c[0], 1 - 0.5 * c[1], 1 - 0.5 * c[2], 1 - 0.5 * c[3]}, "Tunable");
}

// Gather, GatherGreen and GatherAlpha with an offset, through a struct holding texture and sampler
// (FXAA 3.11's FXAA_HLSL_5 path), against the 2×2 footprint computed here.
TEST_F(RealWorld2Render, GatherChannelsMatchTheFootprint) {
    const int TW = 4, TH = 4, W = 8, H = 8;
    Effect effect(device, fixture("gather/GatherChannels.fx"), noCache());
    Texture2D tex(device, TW, TH, false, SurfaceFormat::Color);
    std::vector<Color> texels(TW * TH);
    for (int y = 0; y < TH; ++y)
        for (int x = 0; x < TW; ++x) texels[size_t(y * TW + x)] = Color(10 + 60 * x, 20 + 50 * y, 0, 15 * (x + TW * y));
    tex.SetData(texels);
    effect.Parameters["Scene"].SetValue(tex);
    auto channel = [&](int x, int y, int k) {
        x = std::clamp(x, 0, TW - 1);
        y = std::clamp(y, 0, TH - 1);
        const Color& c = texels[size_t(y * TW + x)];
        return double(k == 0 ? c.R : k == 1 ? c.G : c.A) / 255.0;
    };
    for (int mode = 0; mode < 3; ++mode) {
        effect.Parameters["Channel"].SetValue(float(mode));
        std::vector<float> px = draw(effect, W, H);
        const int k = mode == 0 ? 0 : mode == 1 ? 1 : 3, dx = mode == 2 ? 1 : 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                // SM5 pixel centre (x + 0.5) / W; the footprint starts at floor(u * TW - 0.5) (never
                // an integer here: the target is twice the texture).
                int i0 = int(std::floor((x + 0.5) / W * TW - 0.5)) + dx, j0 = int(std::floor((y + 0.5) / H * TH - 0.5));
                const std::array<double, 4> expected = {channel(i0, j0 + 1, k), channel(i0 + 1, j0 + 1, k), channel(i0 + 1, j0, k), channel(i0, j0, k)};
                for (int c = 0; c < 4; ++c)
                    EXPECT_NEAR(px[size_t(y * W + x) * 4 + size_t(c)], expected[size_t(c)], 1e-5) << "mode " << mode << " pixel " << x << "," << y << " component " << c;
            }
    }
}

}  // namespace
}  // namespace fxport
