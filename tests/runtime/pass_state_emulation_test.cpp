// Pass states GL core lacks, emulated by the runtime and checked by pixels against the same
// comparisons computed on the CPU in double precision: D3D9 alpha test (a discarding pixel-shader
// variant), SRGBWriteEnable (GL_FRAMEBUFFER_SRGB on an sRGB target) and D3D10 comparison samplers
// (GL compare mode on the sampler object; point and linear PCF). Fixture: PassStateEmulation.fx.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "opaque_draw_test.h"
#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::drawQuad;
using test::readFloats;
using test::testDevice;

class PassStateEmulation : public test::OpaqueDrawTest {
protected:
    void draw(const char* technique) {
        effect.CurrentTechnique = effect.Techniques[technique];
        effect.CurrentTechnique->Passes[0].Apply();
        drawQuad(device);
    }
    Effect effect{device, test::runtimeFixture("PassStateEmulation.fx")};
};

// --- alpha test

// Which columns of a W-wide ramp (alpha = (x + 0.5) / W, as SM4 rasterises) survive
// `alpha FUNC ref / 255` (D3D9's comparison, as Wine's d3d9 makes it: output alpha unclamped).
std::vector<bool> survivors(int W, bool (*func)(double, double), int alphaRef) {
    std::vector<bool> out;
    for (int x = 0; x < W; ++x) out.push_back(func((x + 0.5) / W, (alphaRef & 0xFF) / 255.0));
    return out;
}

void expectColumns(RenderTarget2D& target, const std::vector<bool>& kept) {
    std::vector<Color> px(std::size_t(target.Width() * target.Height()));
    target.GetData(px.data(), px.size());
    for (int y = 0; y < target.Height(); ++y)
        for (int x = 0; x < target.Width(); ++x) {
            const Color& c = px[std::size_t(y * target.Width() + x)];
            SCOPED_TRACE("pixel " + std::to_string(x) + "," + std::to_string(y));
            if (kept[std::size_t(x)]) {
                EXPECT_EQ(c.R, 255);
                EXPECT_EQ(c.B, 0);
            } else {  // discarded: the clear colour stays
                EXPECT_EQ(c.R, 0);
                EXPECT_EQ(c.B, 255);
            }
        }
}

TEST_F(PassStateEmulation, AlphaTestDiscardsAsD3D9ComparesOutputAlphaWithAlphaRef) {
    const int W = 16, H = 2;
    RenderTarget2D target(device, W, H, false, SurfaceFormat::Color);
    device.SetRenderTarget(target);
    auto greater = [](double a, double r) { return a > r; };
    auto lessEqual = [](double a, double r) { return a <= r; };

    // AlphaRef = <AlphaReference>, read at each Apply.
    for (int alphaRef : {128, 200, 0x1FF /* only the low 8 bits count: 255 */}) {
        SCOPED_TRACE("AlphaRef " + std::to_string(alphaRef));
        effect.Parameters["AlphaReference"].SetValue(alphaRef);
        device.Clear(Color(0, 0, 255, 255));
        draw("AlphaTestFromParameter");
        std::vector<bool> kept = survivors(W, greater, alphaRef);
        expectColumns(target, kept);
    }
    // The expectations are not trivial: AlphaRef 128 keeps the right half only.
    std::vector<bool> half = survivors(W, greater, 128);
    EXPECT_EQ(std::count(half.begin(), half.end(), true), 8);

    device.Clear(Color(0, 0, 255, 255));
    draw("AlphaTestLiteral");  // AlphaFunc = LessEqual; AlphaRef = 64
    expectColumns(target, survivors(W, lessEqual, 64));

    // A pass that does not enable the alpha test draws every pixel (the test belongs to the pass).
    device.Clear(Color(0, 0, 255, 255));
    draw("NoAlphaTest");
    expectColumns(target, std::vector<bool>(W, true));
}

// --- sRGB write

double linearToSrgb(double c) { return c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055; }

TEST_F(PassStateEmulation, SrgbWriteEncodesIntoAnSrgbTargetOnly) {
    const double out[4] = {0.5, 0.25, 0.03, 1.0};
    effect.Parameters["Output"].SetValue(Vector4(float(out[0]), float(out[1]), float(out[2]), float(out[3])));
    struct Case {
        SurfaceFormat format;
        const char* technique;
        bool encoded;  // what GL does: FRAMEBUFFER_SRGB converts only for sRGB-encoded attachments
    } cases[] = {
        {SurfaceFormat::ColorSRgb, "SrgbWrite", true},
        {SurfaceFormat::ColorSRgb, "LinearWrite", false},
        {SurfaceFormat::Color, "SrgbWrite", false},  // not an sRGB target: written unconverted
        {SurfaceFormat::Color, "LinearWrite", false},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(std::string(surfaceFormatName(c.format)) + " " + c.technique);
        RenderTarget2D target(device, 2, 2, false, c.format);
        device.SetRenderTarget(target);
        device.Clear(Color::Black);
        draw(c.technique);
        std::vector<Color> px(4);
        target.GetData(px.data(), px.size());
        for (const Color& p : px) {
            const std::uint8_t got[4] = {p.R, p.G, p.B, p.A};
            for (int k = 0; k < 4; ++k) {
                // Alpha is never encoded.
                double want = 255 * (c.encoded && k < 3 ? linearToSrgb(out[k]) : out[k]);
                // Rounding allows 0.5; GL leaves the precision of the sRGB encoding to the
                // implementation (llvmpipe is within 0.62 of the exact value), hence 1.
                EXPECT_NEAR(got[k], want, c.encoded ? 1.0 : 0.5 + 1e-9) << "channel " << k;
            }
        }
        device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    }
}

// D3D9 encodes an SRGBWriteEnable pass's colours into any 8-bit target, GL only into sRGB-encoded
// ones: a draw into a SurfaceFormat::Color target (or such a back buffer) is reported once per
// effect, FX1304 at the state's file:line; ColorSRgb and float targets (D3D9 does not encode into
// those either) are not.
TEST_F(PassStateEmulation, SrgbWriteIntoAnUnencodedTargetIsReportedOncePerEffect) {
    std::vector<std::string> warnings;
    EffectWarningHandler previous = SetEffectWarningHandler([&](const std::string& w) {
        if (w.find("SRGBWriteEnable") != std::string::npos) warnings.push_back(w);
    });
    auto said = [&] {
        std::string all;
        for (const std::string& w : warnings) all += w + "\n";
        return all;
    };
    for (SurfaceFormat format : {SurfaceFormat::ColorSRgb, SurfaceFormat::Vector4}) {
        RenderTarget2D target(device, 2, 2, false, format);
        device.SetRenderTarget(target);
        draw("SrgbWrite");
    }
    EXPECT_EQ(warnings.size(), 0u) << said();
    RenderTarget2D color(device, 2, 2, false, SurfaceFormat::Color);
    device.SetRenderTarget(color);
    draw("LinearWrite");
    EXPECT_EQ(warnings.size(), 0u) << said();
    draw("SrgbWrite");
    draw("SrgbWrite");
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    draw("SrgbWrite");  // the back buffer (SurfaceFormat::Color): the same effect, already said
    ASSERT_EQ(warnings.size(), 1u) << said();
    EXPECT_NE(warnings[0].find("PassStateEmulation.fx(61,"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("warning FX1304"), std::string::npos) << warnings[0];
    EXPECT_NE(warnings[0].find("'SRGBWriteEnable'"), std::string::npos) << warnings[0];

    // Another effect with the same pass says it again.
    Effect second{device, test::runtimeFixture("PassStateEmulation.fx")};
    second.CurrentTechnique = second.Techniques["SrgbWrite"];
    second.CurrentTechnique->Passes[0].Apply();
    drawQuad(device);
    EXPECT_EQ(warnings.size(), 2u) << said();
    SetEffectWarningHandler(previous);
}

// --- comparison samplers

// A depth texture whose texels differ from every reference used below.
struct DepthMap {
    int N = 4;
    std::vector<float> depth;
    DepthMap() {
        for (int j = 0; j < N; ++j)
            for (int i = 0; i < N; ++i) depth.push_back(float((i * 3 + j * 5) % 16) / 16.0f + 1.0f / 32.0f);
    }
    double at(int i, int j) const {  // Clamp addressing
        i = std::clamp(i, 0, N - 1);
        j = std::clamp(j, 0, N - 1);
        return depth[std::size_t(j * N + i)];
    }
};

TEST_F(PassStateEmulation, ComparisonSamplersFilterTheComparisonsAsD3D10AndGLDefine) {
    DepthMap map;
    Texture2D shadow(device, map.N, map.N, false, SurfaceFormat::Depth32);
    shadow.SetData(map.depth);
    effect.Parameters["ShadowMap"].SetValue(shadow);
    const int W = 16, H = 16;
    RenderTarget2D target(device, W, H, false, SurfaceFormat::Vector4);
    for (double reference : {0.3, 0.5, 0.71}) {
        SCOPED_TRACE("reference " + std::to_string(reference));
        effect.Parameters["Reference"].SetValue(float(reference));

        // LESS_EQUAL, COMPARISON_MIN_MAG_LINEAR_MIP_POINT: the four nearest texels compared with
        // `reference <= texel` (1 or 0), then weighted bilinearly (D3D10's PCF; GL's LINEAR compare).
        device.SetRenderTarget(target);
        device.Clear(Color::Black);
        draw("PcfLinearFilter");
        device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        std::vector<float> linear = readFloats(target);
        int fractional = 0;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                double tx = (x + 0.5) / W * map.N - 0.5, ty = (y + 0.5) / H * map.N - 0.5;
                int i0 = int(std::floor(tx)), j0 = int(std::floor(ty));
                double fx = tx - i0, fy = ty - j0;
                auto cmp = [&](int i, int j) { return reference <= map.at(i, j) ? 1.0 : 0.0; };
                double want = (1 - fy) * ((1 - fx) * cmp(i0, j0) + fx * cmp(i0 + 1, j0)) +
                              fy * ((1 - fx) * cmp(i0, j0 + 1) + fx * cmp(i0 + 1, j0 + 1));
                fractional += want > 0 && want < 1;
                // llvmpipe weights the comparisons with 8-bit fractions.
                EXPECT_NEAR(linear[std::size_t(4 * (y * W + x))], want, 1.0 / 256 + 1e-6) << "pixel " << x << "," << y;
            }
        EXPECT_GT(fractional, W);  // the filter really mixes comparisons

        // GREATER, COMPARISON_MIN_MAG_MIP_POINT (SampleCmp): the nearest texel only.
        device.SetRenderTarget(target);
        device.Clear(Color::Black);
        draw("PcfPointFilter");
        device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        std::vector<float> point = readFloats(target);
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                int i = (x * map.N) / W, j = (y * map.N) / H;
                double want = reference > map.at(i, j) ? 1.0 : 0.0;
                EXPECT_EQ(point[std::size_t(4 * (y * W + x))], want) << "pixel " << x << "," << y;
            }
    }
}

// --- what cannot be emulated is said once per effect, at load

TEST(PassStateWarnings, TheRuntimeReportsEachDroppedStateOnceWhenTheEffectLoads) {
    std::vector<std::string> reported;
    EffectWarningHandler old = SetEffectWarningHandler([&](const std::string& w) { reported.push_back(w); });
    {
        Effect effect(testDevice(), test::runtimeFixture("../states/UnhonouredStates.fx"));
        EXPECT_EQ(reported.size(), 10u);  // the fixture's ten dropped states
        for (const std::string& w : reported) EXPECT_NE(w.find("UnhonouredStates.fx("), std::string::npos) << w;
        effect.CurrentTechnique->Passes[0].Apply();  // nothing more at Apply
        EXPECT_EQ(reported.size(), 10u);
    }
    std::size_t before = reported.size();
    { Effect clean(testDevice(), test::runtimeFixture("PassStateEmulation.fx")); }
    EXPECT_EQ(reported.size(), before);  // emulated states are not reported
    SetEffectWarningHandler(old);
}

}  // namespace
}  // namespace fxport
