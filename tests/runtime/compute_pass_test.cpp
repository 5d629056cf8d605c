// Compute passes (DeviceOptimizations::ComputePasses, runtime/graphics/src/compute_pass.cpp):
// each pixel shader of tests/fixtures/runtime/ComputePasses.fx is drawn as a full-target quad on a
// device that draws it with the fragment stage and on one that runs it as a compute dispatch; both
// images are compared with the same math computed on the CPU in double precision and must be
// byte-identical to each other, drawn once (the compute device fills its replay store) and again
// (it replays). Draws a dispatch cannot reproduce must be drawn as usual (and still be right).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>

#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::drawQuad;
using test::runtimeFixture;

constexpr int kW = 24, kH = 12;
constexpr double kColorTolerance = 1.0 / 255;  // an 8-bit channel: the rounding, plus D3D9's 1/256-pixel bias
constexpr double kFloatTolerance = 1e-5;

const Vector4 kClear(0.2f, 0.4f, 0.6f, 0.8f);

struct Pixel {
    double v[4];
};

// The effect's Pattern(uv), with frac and sin in double.
Pixel pattern(double u, double v) {
    double f = u * 3.7 + v * 1.3;
    return {{u, v, f - std::floor(f), 0.5 + 0.5 * std::sin(u * 10.0)}};
}

// UV of pixel (x, y) of a full-viewport quad: SM4 samples at pixel centres, D3D9 at integer
// coordinates (the port's half-pixel offset, less its 1/256-pixel bias).
void uvAt(int x, int y, const Viewport& vp, bool d3d9, double& u, double& v) {
    const double shift = d3d9 ? 1.0 / 256 : 0.5;
    u = (x - vp.X + shift) / vp.Width;
    v = (y - vp.Y + shift) / vp.Height;
}

struct Device {
    explicit Device(bool compute, int w = kW, int h = kH) {
        PresentationParameters p;
        p.BackBufferWidth = w;
        p.BackBufferHeight = h;
        p.Optimizations.ComputePasses = compute;
        device = std::make_unique<GraphicsDevice>(p);
        effect = std::make_unique<Effect>(*device, runtimeFixture("ComputePasses.fx"));
        device->BlendState = BlendState::Opaque;
        device->DepthStencilState = DepthStencilState::None;
        device->RasterizerState = RasterizerState::CullCounterClockwise;
    }
    void apply(const std::string& technique) {
        effect->CurrentTechnique = effect->Techniques[technique];
        effect->CurrentTechnique->Passes[0].Apply();
    }
    long dispatched() const { return device->computePassStatistics().dispatched; }
    std::unique_ptr<GraphicsDevice> device;
    std::unique_ptr<Effect> effect;
    std::shared_ptr<SpriteBatch> spriteBatch;  // made by the first draw that needs one, kept as a game keeps it
};

std::vector<float> readTarget(RenderTarget2D& target) {
    const std::size_t n = std::size_t(target.Width()) * std::size_t(target.Height());
    if (target.Format() == SurfaceFormat::Single) {
        std::vector<float> single(n), out(n * 4, 0.0f);
        target.GetData(single.data(), n);
        for (std::size_t i = 0; i < n; ++i) out[i * 4] = single[i], out[i * 4 + 3] = 1;
        return out;
    }
    return test::readFloats(target);
}

// The largest difference of `image` from `expected(x, y)` over the channels `channels` (1..4).
double maxError(const std::vector<float>& image, int w, int h, const std::function<Pixel(int, int)>& expected,
                int channels = 4) {
    double worst = 0;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            Pixel e = expected(x, y);
            for (int c = 0; c < channels; ++c)
                worst = std::max(worst, std::abs(double(image[std::size_t((y * w + x) * 4 + c)]) - e.v[c]));
        }
    return worst;
}

double maxDifference(const std::vector<float>& a, const std::vector<float>& b) {
    double worst = 0;
    for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(double(a[i]) - double(b[i])));
    return worst;
}

bool sameBytes(const std::vector<float>& a, const std::vector<float>& b) {
    return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

// Renders `draw` into a fresh `format` target (cleared to kClear) both ways, twice each (clearing
// between); checks each image against `expected` within `tolerance`, that the compute device's
// images are byte-identical to the fragment stage's, that it dispatched `dispatches` times per
// round and that the second round replayed the interpolants the first one stored.
// Returns the compute device's statistics. `channels`: how many channels `expected` gives.
ComputePassStatistics bothWays(const char* name, SurfaceFormat format, int w, int h, const std::function<void(Device&)>& draw,
                               const std::function<Pixel(int, int)>& expected, double tolerance, long dispatches,
                               int channels = 4, std::vector<float>* image = nullptr) {
    ComputePassStatistics computed;
    std::vector<float> images[2][2];
    for (bool compute : {false, true}) {
        SCOPED_TRACE(compute ? "compute" : "fragment");
        Device d(compute, w, h);
        RenderTarget2D target(*d.device, w, h, false, format, DepthFormat::None);
        for (int round = 0; round < 2; ++round) {
            d.device->SetRenderTarget(target);
            d.device->Clear(ClearOptions::Target, kClear, 1.0f, 0);
            draw(d);
            d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
            images[compute][round] = readTarget(target);
            EXPECT_LE(maxError(images[compute][round], w, h, expected, channels), tolerance);
        }
        const ComputePassStatistics stats = d.device->computePassStatistics();
        EXPECT_EQ(stats.dispatched, compute ? 2 * dispatches : 0);
        EXPECT_EQ(stats.replayed, compute ? dispatches : 0);
        EXPECT_GE(stats.issued, stats.dispatched);
        if (compute) computed = stats;
    }
    EXPECT_TRUE(sameBytes(images[0][0], images[1][0])) << "first draw: compute differs from fragment";
    EXPECT_TRUE(sameBytes(images[0][1], images[1][1])) << "replayed draw: compute differs from fragment";
    EXPECT_TRUE(sameBytes(images[0][0], images[0][1]));
    std::printf("[ compute ] %-28s compute vs fragment: max difference %.3g (first), %.3g (replayed)\n", name,
                maxDifference(images[0][0], images[1][0]), maxDifference(images[0][1], images[1][1]));
    if (image) *image = images[1][1];
    return computed;
}

Pixel clearOr(bool inside, const Pixel& p) { return inside ? p : Pixel{{kClear.X, kClear.Y, kClear.Z, kClear.W}}; }

TEST(ComputePasses, OpaqueWrite) {
    for (auto [w, h] : {std::pair{kW, kH}, std::pair{16, 16}}) {  // a square target: pixel centres on the diagonal
        bothWays("opaque write", SurfaceFormat::Color, w, h, [](Device& d) { d.apply("Pattern"); drawQuad(*d.device); },
                 [&](int x, int y) { double u, v; uvAt(x, y, Viewport(0, 0, w, h), false, u, v); return pattern(u, v); },
                 kColorTolerance * 0.6, 1);
        bothWays("opaque write, Vector4", SurfaceFormat::Vector4, w, h,
                 [](Device& d) { d.apply("Pattern"); drawQuad(*d.device); },
                 [&](int x, int y) { double u, v; uvAt(x, y, Viewport(0, 0, w, h), false, u, v); return pattern(u, v); },
                 kFloatTolerance, 1);
    }
}

TEST(ComputePasses, FullscreenQuadWithD3D9HalfPixelOffset) {
    bothWays("D3D9 FullscreenQuad", SurfaceFormat::Color, kW, kH,
             [](Device& d) {
                 d.apply("PatternD3D9");
                 FullscreenQuad quad(*d.device);
                 quad.Draw(*d.device);
             },
             [](int x, int y) { double u, v; uvAt(x, y, Viewport(0, 0, kW, kH), true, u, v); return pattern(u, v); },
             kColorTolerance, 1);
}

// A flat (nointerpolation) varying takes D3D's provoking vertex, the first (the device sets GL's
// first-vertex convention): the quad's first triangle (top-left, top-right, bottom-left) shows
// top-left's UV (0,0), the second (bottom-left, top-right, bottom-right) bottom-left's (0,1). On a square target pixel centres lie on the shared edge; D3D's
// top-left rule gives them to the second triangle, whose left edge it is.
TEST(ComputePasses, FlatVaryingAndTheFillRuleOnTheDiagonal) {
    for (auto [w, h] : {std::pair{16, 16}, std::pair{kW, kH}}) {
        bothWays("flat varying, fill rule", SurfaceFormat::Color, w, h, [](Device& d) { d.apply("Flat"); drawQuad(*d.device); },
                 [&](int x, int y) {
                     // Centre (x+0.5, y+0.5) against the edge x/w + y/h = 1, in integers.
                     const long side = long(2 * x + 1) * h + long(2 * y + 1) * w - 2L * w * h;
                     return side < 0 ? Pixel{{0, 0, 0, 1}} : Pixel{{0, 1, 0, 1}};
                 },
                 0.0, 1);
    }
}

TEST(ComputePasses, WriteMaskKeepsMaskedChannels) {
    bothWays("write mask", SurfaceFormat::Color, kW, kH,
             [](Device& d) {
                 BlendState masked = BlendState::Opaque;
                 masked.ColorWriteChannels = ColorWriteChannels::Red | ColorWriteChannels::Alpha;
                 d.device->BlendState = masked;
                 d.apply("Pattern");
                 drawQuad(*d.device);
             },
             [](int x, int y) {
                 double u, v;
                 uvAt(x, y, Viewport(0, 0, kW, kH), false, u, v);
                 Pixel p = pattern(u, v);
                 return Pixel{{p.v[0], kClear.Y, kClear.Z, p.v[3]}};
             },
             kColorTolerance * 0.6, 1);
}

TEST(ComputePasses, ScissorClipsTheDispatch) {
    const Rectangle scissor(5, 3, 9, 6);
    bothWays("scissor", SurfaceFormat::Color, kW, kH,
             [&](Device& d) {
                 RasterizerState r = RasterizerState::CullCounterClockwise;
                 r.ScissorTestEnable = true;
                 d.device->RasterizerState = r;
                 d.device->ScissorRectangle = scissor;
                 d.apply("Pattern");
                 drawQuad(*d.device);
             },
             [&](int x, int y) {
                 double u, v;
                 uvAt(x, y, Viewport(0, 0, kW, kH), false, u, v);
                 return clearOr(scissor.Contains(x, y), pattern(u, v));
             },
             kColorTolerance * 0.6, 1);
}

// A quad over part of the target (a sprite): the bounds step dispatches only over its rectangle;
// the pixels around it keep the clear. Window x 6..15, y 3..9 of 24x12: no centre on an edge.
TEST(ComputePasses, PartialQuadLeavesTheRestOfTheTarget) {
    auto corner = [](float x, float y) { return VertexPositionTexture(Vector3(x, y, 0), Vector2((x + 1) / 2, (1 - y) / 2)); };
    const VertexPositionTexture tl = corner(-0.5f, 0.5f), tr = corner(0.25f, 0.5f), bl = corner(-0.5f, -0.5f), br = corner(0.25f, -0.5f);
    const VertexPositionTexture quad[6] = {tl, tr, bl, bl, tr, br};
    bothWays("partial quad", SurfaceFormat::Color, kW, kH,
             [&](Device& d) {
                 d.apply("Pattern");
                 d.device->DrawUserPrimitives(PrimitiveType::TriangleList, quad, 0, 2);
             },
             [&](int x, int y) {
                 double u, v;
                 uvAt(x, y, Viewport(0, 0, kW, kH), false, u, v);
                 return clearOr(x >= 6 && x < 15 && y >= 3 && y < 9, pattern(u, v));
             },
             kColorTolerance * 0.6, 1);
}

TEST(ComputePasses, SmallerViewport) {
    const Viewport vp(4, 2, 11, 7);
    bothWays("smaller viewport", SurfaceFormat::Color, kW, kH,
             [&](Device& d) {
                 d.device->Viewport = vp;
                 d.apply("Pattern");
                 drawQuad(*d.device);
             },
             [&](int x, int y) {
                 double u, v;
                 uvAt(x, y, vp, false, u, v);
                 return clearOr(x >= vp.X && x < vp.X + vp.Width && y >= vp.Y && y < vp.Y + vp.Height, pattern(u, v));
             },
             kColorTolerance * 0.6, 1);
}

TEST(ComputePasses, MinBlend) {
    bothWays("Min blend", SurfaceFormat::Color, kW, kH,
             [](Device& d) {
                 BlendState min = BlendState::Opaque;
                 min.ColorBlendFunction = min.AlphaBlendFunction = BlendFunction::Min;
                 min.ColorSourceBlend = min.AlphaSourceBlend = Blend::One;
                 min.ColorDestinationBlend = min.AlphaDestinationBlend = Blend::One;
                 d.device->BlendState = min;
                 d.apply("Pattern");
                 drawQuad(*d.device);
             },
             [](int x, int y) {
                 double u, v;
                 uvAt(x, y, Viewport(0, 0, kW, kH), false, u, v);
                 Pixel p = pattern(u, v);
                 const double c[4] = {kClear.X, kClear.Y, kClear.Z, kClear.W};
                 for (int i = 0; i < 4; ++i) p.v[i] = std::min(p.v[i], c[i]);
                 return p;
             },
             kColorTolerance * 0.6, 1);
}

// One/One on a 32-bit float target is the blender's fp32 addition (narrower targets fall back).
TEST(ComputePasses, AdditiveBlendOnAFloatTarget) {
    bothWays("One/One on Vector4", SurfaceFormat::Vector4, kW, kH,
             [](Device& d) {
                 BlendState add = BlendState::Opaque;
                 add.ColorDestinationBlend = add.AlphaDestinationBlend = Blend::One;
                 d.device->BlendState = add;
                 d.apply("Pattern");
                 drawQuad(*d.device);
             },
             [](int x, int y) {
                 double u, v;
                 uvAt(x, y, Viewport(0, 0, kW, kH), false, u, v);
                 Pixel p = pattern(u, v);
                 const double c[4] = {kClear.X, kClear.Y, kClear.Z, kClear.W};
                 for (int i = 0; i < 4; ++i) p.v[i] += c[i];
                 return p;
             },
             kFloatTolerance, 1);
}

// Culling follows the winding as seen: the quad drawn counter-clockwise is culled by XNA's default
// and drawn with CullMode::None (and with CullClockwiseFace), both ways.
TEST(ComputePasses, CullingFollowsTheWindingAsSeen) {
    for (CullMode mode : {CullMode::CullCounterClockwiseFace, CullMode::None, CullMode::CullClockwiseFace}) {
        SCOPED_TRACE(int(mode));
        bothWays("counter-clockwise quad", SurfaceFormat::Color, kW, kH,
                 [&](Device& d) {
                     RasterizerState r = RasterizerState::CullNone;
                     r.CullMode = mode;
                     d.device->RasterizerState = r;
                     d.apply("Pattern");
                     std::vector<VertexPositionTexture> v = test::fullscreenQuad();
                     std::swap(v[1], v[2]);  // each triangle counter-clockwise
                     std::swap(v[4], v[5]);
                     d.device->DrawUserPrimitives(PrimitiveType::TriangleList, v.data(), 0, 2);
                 },
                 [&](int x, int y) {
                     double u, v;
                     uvAt(x, y, Viewport(0, 0, kW, kH), false, u, v);
                     return clearOr(mode != CullMode::CullCounterClockwiseFace, pattern(u, v));
                 },
                 kColorTolerance * 0.6, 1);
    }
}

TEST(ComputePasses, DiscardKeepsThePixel) {
    bothWays("discard", SurfaceFormat::Color, kW, kH, [](Device& d) { d.apply("Discard"); drawQuad(*d.device); },
             [](int x, int y) {
                 double u, v;
                 uvAt(x, y, Viewport(0, 0, kW, kH), false, u, v);
                 return clearOr(u >= 0.5, pattern(u, v));
             },
             kColorTolerance * 0.6, 1);
}

// Three targets of different formats from one pixel shader.
TEST(ComputePasses, MultipleRenderTargets) {
    std::vector<float> images[2][2][3];  // [compute][round][target]
    for (bool compute : {false, true}) {
        SCOPED_TRACE(compute ? "compute" : "fragment");
        Device d(compute);
        RenderTarget2D color(*d.device, kW, kH, false, SurfaceFormat::Color, DepthFormat::None);
        RenderTarget2D vector4(*d.device, kW, kH, false, SurfaceFormat::Vector4, DepthFormat::None);
        RenderTarget2D single(*d.device, kW, kH, false, SurfaceFormat::Single, DepthFormat::None);
        for (int round = 0; round < 2; ++round) {
            d.device->SetRenderTargets({RenderTargetBinding(&color), RenderTargetBinding(&vector4), RenderTargetBinding(&single)});
            d.device->Clear(ClearOptions::Target, kClear, 1.0f, 0);
            d.apply("MRT");
            drawQuad(*d.device);
            d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
            std::vector<float>* image = images[compute][round];
            image[0] = readTarget(color);
            image[1] = readTarget(vector4);
            image[2] = readTarget(single);
            auto uv = [](int x, int y, double& u, double& v) { uvAt(x, y, Viewport(0, 0, kW, kH), false, u, v); };
            EXPECT_LE(maxError(image[0], kW, kH, [&](int x, int y) { double u, v; uv(x, y, u, v); return pattern(u, v); }),
                      kColorTolerance * 0.6);
            EXPECT_LE(maxError(image[1], kW, kH,
                               [&](int x, int y) {
                                   double u, v;
                                   uv(x, y, u, v);
                                   return Pixel{{u * 4 - 1, v * 4 - 1, u * v * 100, -2}};
                               }),
                      1e-4);
            EXPECT_LE(maxError(image[2], kW, kH,
                               [&](int x, int y) {
                                   double u, v;
                                   uv(x, y, u, v);
                                   return Pixel{{v * 3 + u, 0, 0, 1}};
                               },
                               1),
                      kFloatTolerance);
        }
        EXPECT_EQ(d.dispatched(), compute ? 2 : 0);
        EXPECT_EQ(d.device->computePassStatistics().replayed, compute ? 1 : 0);
    }
    for (int round = 0; round < 2; ++round)
        for (int t = 0; t < 3; ++t) {
            EXPECT_TRUE(sameBytes(images[0][round][t], images[1][round][t])) << "round " << round << ", target " << t;
            std::printf("[ compute ] MRT target %d, round %d        compute vs fragment: max difference %.3g\n", t, round,
                        maxDifference(images[0][round][t], images[1][round][t]));
        }
}

// A SpriteBatch sprite over the whole target with a custom pixel-shader-only effect.
TEST(ComputePasses, FullTargetSpriteWithCustomEffect) {
    const int tw = 6, th = 3;
    std::vector<Color> texels;
    for (int i = 0; i < tw * th; ++i) texels.push_back(Color(std::uint8_t(i * 13), std::uint8_t(255 - i * 11), std::uint8_t(i * 7), 255));
    bothWays("SpriteBatch full-target sprite", SurfaceFormat::Color, kW, kH,
             [&](Device& d) {
                 Texture2D texture(*d.device, tw, th);
                 texture.SetData(texels.data(), texels.size());
                 if (!d.spriteBatch) d.spriteBatch = std::make_shared<SpriteBatch>(*d.device);
                 SpriteBatch& batch = *d.spriteBatch;
                 d.effect->CurrentTechnique = d.effect->Techniques["Sprite"];
                 batch.Begin(SpriteSortMode::Immediate, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr,
                             *d.effect);
                 batch.Draw(texture, Rectangle(0, 0, kW, kH), Color::White);
                 batch.End();
             },
             [&](int x, int y) {
                 // XNA's sprite matrix has the -0.5 that cancels D3D9's pixel centres: the texture
                 // coordinate of pixel x is (x + 0.5 + 1/256) / width (pending_clear.cpp).
                 double u, v;
                 uvAt(x, y, Viewport(0, 0, kW, kH), false, u, v);
                 const Color& c = texels[std::size_t(int(v * th) * tw + int(u * tw))];
                 Pixel p = pattern(u, v);
                 const double t[4] = {c.R / 255.0, c.G / 255.0, c.B / 255.0, c.A / 255.0};
                 for (int i = 0; i < 4; ++i) p.v[i] = t[i] * 0.5 + p.v[i] * 0.5;
                 return p;
             },
             kColorTolerance, 1);
}

// A value on a threshold (ComputePasses.fx, ThresholdPS): at each pixel centre uv * 23 is x + 0.5
// (or y + 0.5) up to the interpolant's last bit, so frac() < 0.5 goes either way and only the
// rasteriser's own interpolants give the fragment stage's pixels. Odd-sized target; uv (channels
// 0, 1) is checked against the CPU, the thresholds only against the fragment stage (byte-identical).
TEST(ComputePasses, ThresholdOnAnInterpolantIsExact) {
    constexpr int w = 23, h = 23;
    std::vector<float> image;
    bothWays("threshold on uv * 23", SurfaceFormat::Vector4, w, h, [](Device& d) { d.apply("Threshold"); drawQuad(*d.device); },
             [&](int x, int y) { double u, v; uvAt(x, y, Viewport(0, 0, w, h), false, u, v); return Pixel{{u, v, 0, 0}}; },
             kFloatTolerance, 1, 2, &image);
    // Only 0 and 1, and both: the pixels sit on the threshold (else this would test nothing).
    long ones = 0;
    for (int i = 0; i < w * h; ++i)
        for (int c : {2, 3}) {
            const float value = image[std::size_t(i * 4 + c)];
            EXPECT_TRUE(value == 0.0f || value == 1.0f);
            ones += value == 1.0f;
        }
    EXPECT_GT(ones, 0);
    EXPECT_LT(ones, 2 * w * h);
    std::printf("[ compute ] threshold: %ld of %d values on the 1 side\n", ones, 2 * w * h);
}

// Perspective: w = 1 + u per vertex. A perspective-correct input may not replay (the GPU draws it
// with the fragment stage); u = s / (2 - s) at screen position s in both triangles of the quad.
TEST(ComputePasses, PerspectiveInputWithWNotOneFallsBackOnTheGpu) {
    const ComputePassStatistics stats = bothWays(
        "perspective quad, w = 1 + u", SurfaceFormat::Vector4, kW, kH,
        [](Device& d) { d.apply("Perspective"); drawQuad(*d.device); },
        [](int x, int y) {
            double s, t;
            uvAt(x, y, Viewport(0, 0, kW, kH), false, s, t);
            return Pixel{{s / (2 - s), 0, 0, 0}};
        },
        kFloatTolerance, 0, 1);
    EXPECT_EQ(stats.fellBack.at("w != 1 with a perspective-interpolated input"), 2);
    EXPECT_EQ(stats.issued, 2);  // sent as compute passes, drawn as usual by the GPU
}

// The same quad with a noperspective input replays: screen-linear uv.
TEST(ComputePasses, NoperspectiveInputReplaysWhateverW) {
    bothWays("noperspective, w = 1 + u", SurfaceFormat::Vector4, kW, kH,
             [](Device& d) { d.apply("ScreenLinear"); drawQuad(*d.device); },
             [](int x, int y) {
                 double s, t;
                 uvAt(x, y, Viewport(0, 0, kW, kH), false, s, t);
                 return Pixel{{s, t, 0, 1}};
             },
             kFloatTolerance, 1);
}

// Two triangles that cover the same pixels (the first triangle twice) add twice under One/One: one
// stored value per pixel cannot do that, so the GPU draws them with the fragment stage.
TEST(ComputePasses, OverlappingTrianglesFallBackOnTheGpu) {
    std::vector<VertexPositionTexture> twice = test::fullscreenQuad();
    twice.resize(3);
    twice.insert(twice.end(), twice.begin(), twice.end());
    const ComputePassStatistics stats = bothWays(
        "one triangle twice, One/One", SurfaceFormat::Vector4, kW, kH,
        [&](Device& d) {
            BlendState add = BlendState::Opaque;
            add.ColorDestinationBlend = add.AlphaDestinationBlend = Blend::One;
            d.device->BlendState = add;
            d.apply("Pattern");
            d.device->DrawUserPrimitives(PrimitiveType::TriangleList, twice.data(), 0, 2);
        },
        [](int x, int y) {
            double u, v;
            uvAt(x, y, Viewport(0, 0, kW, kH), false, u, v);
            Pixel p = pattern(u, v);
            const double c[4] = {kClear.X, kClear.Y, kClear.Z, kClear.W};
            const bool inside = u + v < 1;  // the top-left triangle; no pixel centre on its diagonal at 24x12
            for (int i = 0; i < 4; ++i) p.v[i] = c[i] + (inside ? 2 * p.v[i] : 0);
            return p;
        },
        2 * kFloatTolerance, 0);
    EXPECT_EQ(stats.fellBack.at("triangles that may cover a pixel twice"), 2);
}

// One replay entry, two sprites at different places: the compare step sees the capture change
// and refills (the pixels are the fragment stage's each time); the same sprite again replays.
TEST(ComputePasses, ChangedVerticesRefillTheReplayStore) {
    auto quadAt = [](float x0, float x1) {
        auto corner = [](float x, float y) { return VertexPositionTexture(Vector3(x, y, 0), Vector2((x + 1) / 2, (1 - y) / 2)); };
        const VertexPositionTexture tl = corner(x0, 0.5f), tr = corner(x1, 0.5f), bl = corner(x0, -0.5f), br = corner(x1, -0.5f);
        return std::vector<VertexPositionTexture>{tl, tr, bl, bl, tr, br};
    };
    // Window x 6..15 and 9..18, y 3..9 of 24x12: no pixel centre on an edge.
    const std::vector<VertexPositionTexture> quads[3] = {quadAt(-0.5f, 0.25f), quadAt(-0.25f, 0.5f), quadAt(-0.25f, 0.5f)};
    const int left[3] = {6, 9, 9};
    std::vector<float> images[2][3];
    for (bool compute : {false, true}) {
        SCOPED_TRACE(compute ? "compute" : "fragment");
        Device d(compute);
        RenderTarget2D target(*d.device, kW, kH, false, SurfaceFormat::Color, DepthFormat::None);
        for (int i = 0; i < 3; ++i) {
            d.device->SetRenderTarget(target);
            d.device->Clear(ClearOptions::Target, kClear, 1.0f, 0);
            d.apply("Pattern");
            d.device->DrawUserPrimitives(PrimitiveType::TriangleList, quads[i].data(), 0, 2);
            d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
            images[compute][i] = readTarget(target);
            EXPECT_LE(maxError(images[compute][i], kW, kH,
                               [&](int x, int y) {
                                   double u, v;
                                   uvAt(x, y, Viewport(0, 0, kW, kH), false, u, v);
                                   return clearOr(x >= left[i] && x < left[i] + 9 && y >= 3 && y < 9, pattern(u, v));
                               }),
                      kColorTolerance * 0.6);
        }
        const ComputePassStatistics stats = d.device->computePassStatistics();
        EXPECT_EQ(stats.dispatched, compute ? 3 : 0);
        EXPECT_EQ(stats.replayed, compute ? 1 : 0);  // the third draw
        EXPECT_EQ(stats.entries, compute ? 1 : 0);
    }
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(sameBytes(images[0][i], images[1][i])) << "draw " << i;
}

// A viewport smaller than the target and a scissor cutting it: the fill draws the viewport without
// the scissor, the dispatch keeps to both.
TEST(ComputePasses, SmallerViewportAndScissor) {
    const Viewport vp(4, 2, 11, 7);
    const Rectangle scissor(6, 1, 20, 5);
    bothWays("viewport and scissor", SurfaceFormat::Color, kW, kH,
             [&](Device& d) {
                 RasterizerState r = RasterizerState::CullCounterClockwise;
                 r.ScissorTestEnable = true;
                 d.device->RasterizerState = r;
                 d.device->ScissorRectangle = scissor;
                 d.device->Viewport = vp;
                 d.apply("Pattern");
                 drawQuad(*d.device);
             },
             [&](int x, int y) {
                 double u, v;
                 uvAt(x, y, vp, false, u, v);
                 const bool inViewport = x >= vp.X && x < vp.X + vp.Width && y >= vp.Y && y < vp.Y + vp.Height;
                 return clearOr(inViewport && scissor.Contains(x, y), pattern(u, v));
             },
             kColorTolerance * 0.6, 1);
}

// Replay entries stay within $FXPORT_COMPUTE_PASS_CACHE_MB: at 256x256 an entry of PatternPS (the
// stamp and uv.xy) is 768 KiB, so 1 MiB holds one; two viewports in turn evict each other (and each
// draw refills), the pixels still the fragment stage's. With 0 nothing fits: drawn as usual.
TEST(ComputePasses, ReplayEntriesStayWithinTheByteBound) {
    constexpr int w = 256, h = 256;
    const Viewport viewports[2] = {Viewport(0, 0, w, h), Viewport(16, 8, 200, 100)};
    std::vector<float> images[2][4];
    for (bool compute : {false, true}) {
        SCOPED_TRACE(compute ? "compute" : "fragment");
        setenv("FXPORT_COMPUTE_PASS_CACHE_MB", "1", 1);
        Device d(compute, w, h);
        unsetenv("FXPORT_COMPUTE_PASS_CACHE_MB");
        RenderTarget2D target(*d.device, w, h, false, SurfaceFormat::Color, DepthFormat::None);
        for (int i = 0; i < 4; ++i) {
            d.device->SetRenderTarget(target);
            d.device->Clear(ClearOptions::Target, kClear, 1.0f, 0);
            d.device->Viewport = viewports[i % 2];
            d.apply("Pattern");
            drawQuad(*d.device);
            d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
            images[compute][i] = readTarget(target);
        }
        const ComputePassStatistics stats = d.device->computePassStatistics();
        EXPECT_EQ(stats.dispatched, compute ? 4 : 0);
        EXPECT_EQ(stats.replayed, 0);
        EXPECT_EQ(stats.entries, compute ? 1 : 0);
        // The store (3 layers of 4 bytes) and the captured vertices, within the bound.
        EXPECT_GE(stats.entryBytes, compute ? std::int64_t(w) * h * 3 * 4 : 0);
        EXPECT_LE(stats.entryBytes, compute ? std::int64_t(1) << 20 : 0);
        EXPECT_EQ(stats.evicted, compute ? 3 : 0);
    }
    for (int i = 0; i < 4; ++i) EXPECT_TRUE(sameBytes(images[0][i], images[1][i])) << "draw " << i;

    setenv("FXPORT_COMPUTE_PASS_CACHE_MB", "0", 1);
    Device none(true, w, h);
    unsetenv("FXPORT_COMPUTE_PASS_CACHE_MB");
    none.apply("Pattern");
    drawQuad(*none.device);
    const ComputePassStatistics stats = none.device->computePassStatistics();
    EXPECT_EQ(stats.dispatched, 0);
    EXPECT_EQ(stats.fellBack.at("replay store of 1 MiB over FXPORT_COMPUTE_PASS_CACHE_MB=0"), 1);
}

// Draws a dispatch cannot reproduce are drawn as usual: counted as fallen back, not dispatched,
// and their pixels are still right.
TEST(ComputePasses, DerivativesFallBack) {
    Device d(true);
    RenderTarget2D target(*d.device, kW, kH, false, SurfaceFormat::Vector4, DepthFormat::None);
    d.device->SetRenderTarget(target);
    d.apply("Derivative");
    drawQuad(*d.device);
    d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    EXPECT_EQ(d.dispatched(), 0);
    EXPECT_EQ(d.device->computePassStatistics().fellBack["pixel shader: uses dFdx"], 1);
    // ddx(uv.x) * 8 = 8 / width across the quad, ddy(uv.y) * 8 = 8 / height.
    EXPECT_LE(maxError(readTarget(target), kW, kH, [](int, int) { return Pixel{{8.0 / kW, 8.0 / kH, 0, 1}}; }), 1e-5);
}

TEST(ComputePasses, DepthTestFallsBack) {
    Device d(true);
    RenderTarget2D target(*d.device, kW, kH, false, SurfaceFormat::Color, DepthFormat::Depth24Stencil8);
    d.device->SetRenderTarget(target);
    d.device->Clear(ClearOptions::Target | ClearOptions::DepthBuffer, kClear, 1.0f, 0);
    d.device->DepthStencilState = DepthStencilState::Default;
    d.apply("Pattern");
    drawQuad(*d.device, 0.5f);
    d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    EXPECT_EQ(d.dispatched(), 0);
    EXPECT_EQ(d.device->computePassStatistics().fellBack["depth test or write"], 1);
    EXPECT_LE(maxError(readTarget(target), kW, kH,
                       [](int x, int y) { double u, v; uvAt(x, y, Viewport(0, 0, kW, kH), false, u, v); return pattern(u, v); }),
              kColorTolerance * 0.6);
}

// A target without a depth buffer passes every depth test and takes no depth writes (GL), so the
// depth state does not stop a dispatch there.
TEST(ComputePasses, DepthStateOfATargetWithoutDepthBuffer) {
    bothWays("depth state, no depth buffer", SurfaceFormat::Color, kW, kH,
             [](Device& d) {
                 d.device->DepthStencilState = DepthStencilState::Default;
                 d.apply("Pattern");
                 drawQuad(*d.device, 0.5f);
             },
             [](int x, int y) { double u, v; uvAt(x, y, Viewport(0, 0, kW, kH), false, u, v); return pattern(u, v); },
             kColorTolerance * 0.6, 1);
}

// A depth test that writes nothing and cannot fail against the buffer's clear (DepthRead against
// the far clear: the deferred G-buffer's clear quad) dispatches; the buffer still holds the clear
// afterwards (a quad at depth 0.5 under LessEqual then draws everywhere). After a draw wrote depth,
// the same state falls back (the contents are no longer one known value).
TEST(ComputePasses, DepthReadAgainstTheFarClearDispatches) {
    std::vector<float> images[2];
    long dispatched[2] = {0, 0}, fellBack[2] = {0, 0};
    for (bool compute : {false, true}) {
        Device d(compute);
        RenderTarget2D target(*d.device, kW, kH, false, SurfaceFormat::Color, DepthFormat::Depth24Stencil8);
        for (int round = 0; round < 2; ++round) {
            d.device->SetRenderTarget(target);
            d.device->Clear(ClearOptions::Target | ClearOptions::DepthBuffer, kClear, 1.0f, 0);
            d.device->DepthStencilState = DepthStencilState::DepthRead;
            d.apply("Pattern");
            drawQuad(*d.device, 0.25f);
        }
        d.device->DepthStencilState = DepthStencilState::Default;  // writes 0.5 everywhere
        d.apply("Threshold");
        drawQuad(*d.device, 0.5f);
        d.device->DepthStencilState = DepthStencilState::DepthRead;  // 0.75 > 0.5: fails everywhere
        d.apply("Pattern");
        drawQuad(*d.device, 0.75f);
        // The buffer exists now: the same clear quad against a pending far clear dispatches too and
        // leaves the clear pending; a depth-writing quad over the left half then draws there (the
        // clear ran before it), the right half keeps the compute pass's pattern.
        d.device->Clear(ClearOptions::Target | ClearOptions::DepthBuffer, kClear, 1.0f, 0);
        d.device->DepthStencilState = DepthStencilState::DepthRead;
        d.apply("Pattern");
        drawQuad(*d.device, 0.25f);
        RasterizerState left = RasterizerState::CullCounterClockwise;
        left.ScissorTestEnable = true;
        d.device->RasterizerState = left;
        d.device->ScissorRectangle = Rectangle(0, 0, kW / 2, kH);
        d.device->DepthStencilState = DepthStencilState::Default;
        d.apply("Threshold");
        drawQuad(*d.device, 0.5f);
        d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        images[compute] = readTarget(target);  // waits for the GPU, so its counters are read in full
        dispatched[compute] = d.device->computePassStatistics().dispatched;
        fellBack[compute] = d.device->computePassStatistics().fellBack["depth test or write"];
    }
    EXPECT_EQ(dispatched[0], 0);
    EXPECT_EQ(dispatched[1], 3);
    EXPECT_EQ(fellBack[1], 3);  // the depth-writing quads and the DepthRead quad after the first
    EXPECT_TRUE(sameBytes(images[0], images[1]));
    // The right half is the pattern (the last DepthRead quad, drawn by the compute pass).
    double worst = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = kW / 2; x < kW; ++x) {
            double u, v;
            uvAt(x, y, Viewport(0, 0, kW, kH), false, u, v);
            const Pixel e = pattern(u, v);
            for (int c = 0; c < 4; ++c)
                worst = std::max(worst, std::abs(double(images[1][std::size_t((y * kW + x) * 4 + c)]) - e.v[c]));
        }
    EXPECT_LE(worst, kColorTolerance * 0.6);
}

TEST(ComputePasses, ThreeTrianglesAreNotACandidate) {
    Device d(true);
    RenderTarget2D target(*d.device, kW, kH, false, SurfaceFormat::Color, DepthFormat::None);
    d.device->SetRenderTarget(target);
    d.apply("Pattern");
    std::vector<VertexPositionTexture> vertices = test::fullscreenQuad();
    vertices.insert(vertices.end(), vertices.begin(), vertices.begin() + 3);  // the first triangle again
    d.device->DrawUserPrimitives(PrimitiveType::TriangleList, vertices.data(), 0, 3);
    d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    EXPECT_EQ(d.dispatched(), 0);
    EXPECT_TRUE(d.device->computePassStatistics().fellBack.empty());
    EXPECT_LE(maxError(readTarget(target), kW, kH,
                       [](int x, int y) { double u, v; uvAt(x, y, Viewport(0, 0, kW, kH), false, u, v); return pattern(u, v); }),
              kColorTolerance * 0.6);
}

}  // namespace
}  // namespace fxport

int main(int argc, char** argv) {
    ::testing::InitGoogleTest(&argc, argv);
    unsetenv("FXPORT_COMPUTE_PASSES");  // each device here says itself whether it uses compute passes
    return RUN_ALL_TESTS();
}
