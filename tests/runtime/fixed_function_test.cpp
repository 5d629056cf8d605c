// D3D9 fixed-function states emulated by the runtime (GraphicsDevice::FixedFunction, set by an
// effect pass's D3D9 states or by the program): fog, point size and sprites, user clip planes,
// alpha test, flat shading. Each render is checked pixel by pixel against the D3D9 formula computed
// here on the CPU in double precision, with D3D9's pixel centres (vs_3_0: pixel i samples NDC
// 2i/W - 1), so a half-pixel or formula slip fails.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::readFloats;
using test::testDevice;

const char* const kSource = R"(
float2 W = float2(1, 1);  // clip-space w at the left and right edge (x = -1, +1)

struct FogOut { float4 pos : POSITION0; float fog : FOG; float2 uv : TEXCOORD0; };
struct SpecularOut { float4 pos : POSITION0; float4 specular : COLOR1; float2 uv : TEXCOORD0; };
struct SizeOut { float4 pos : POSITION0; float size : PSIZE; float2 uv : TEXCOORD0; };
struct ColourOut { float4 pos : POSITION0; float4 colour : COLOR0; float2 uv : TEXCOORD0; };

float4 place(float3 p, float u) { float w = lerp(W.x, W.y, u); return float4(p * w, w); }
FogOut FogVS(float3 p : POSITION0, float2 uv : TEXCOORD0) { FogOut o; o.pos = place(p, uv.x); o.fog = uv.x; o.uv = uv; return o; }
SpecularOut SpecularVS(float3 p : POSITION0, float2 uv : TEXCOORD0) {
    SpecularOut o; o.pos = place(p, uv.x); o.specular = float4(1, 1, 1, uv.x); o.uv = uv; return o;
}
SizeOut SizeVS(float3 p : POSITION0, float2 uv : TEXCOORD0) { SizeOut o; o.pos = float4(p, 1); o.size = uv.x; o.uv = uv; return o; }
ColourOut ColourVS(float3 p : POSITION0, float4 c : COLOR0) { ColourOut o; o.pos = float4(p, 1); o.colour = c; o.uv = 0; return o; }

float4 Blue(float2 uv : TEXCOORD0) : COLOR0 { return float4(0, 0, 1, 0.5); }
float4 Coordinates(float2 uv : TEXCOORD0) : COLOR0 { return float4(uv, 0, 1); }
float4 Colour(float4 c : COLOR0) : COLOR0 { return c; }
float4 Alpha(float2 uv : TEXCOORD0) : COLOR0 { return float4(1, 0, 0, uv.y); }

technique Fog { pass P { VertexShader = compile vs_3_0 FogVS(); PixelShader = compile ps_3_0 Blue(); } }
technique Specular { pass P { VertexShader = compile vs_3_0 SpecularVS(); PixelShader = compile ps_3_0 Blue(); } }
technique Sprite { pass P { VertexShader = compile vs_3_0 FogVS(); PixelShader = compile ps_3_0 Coordinates(); } }
technique ShaderSize { pass P { VertexShader = compile vs_3_0 SizeVS(); PixelShader = compile ps_3_0 Coordinates(); } }
technique Colours { pass P { VertexShader = compile vs_3_0 ColourVS(); PixelShader = compile ps_3_0 Colour(); } }
technique AlphaRamp { pass P { VertexShader = compile vs_3_0 FogVS(); PixelShader = compile ps_3_0 Alpha(); } }
technique PassFog {
    pass P {
        VertexShader = compile vs_3_0 FogVS(); PixelShader = compile ps_3_0 Blue();
        FogEnable = true; FogTableMode = Linear; FogStart = 0.25; FogEnd = 0.75; FogColor = 0xFF00FF00;
    }
}
technique PassPoints {
    pass P {
        VertexShader = compile vs_3_0 FogVS(); PixelShader = compile ps_3_0 Coordinates();
        PointSize = 9; PointSize_Min = 2; PointSize_Max = 30; PointSpriteEnable = true;
        ClipPlaneEnable = 5; ClipPlane[0] = float4(1, 0, 0, 0.5); ClipPlane[2] = float4(0, 1, 0, 0);
        ShadeMode = Flat; AlphaTestEnable = true; AlphaFunc = Greater; AlphaRef = 0x180;
    }
}
)";

constexpr int kW = 32, kH = 16;

class FixedFunction : public ::testing::Test {
protected:
    void SetUp() override {
        device.SetRenderTarget(target);
        device.Clear(Color(0, 0, 0, 0));
    }
    void TearDown() override { device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr)); }

    // Applies the technique, then D3D's "nothing set" states and `states` (as a program does
    // after Apply()).
    void apply(const char* technique, const std::function<void(FixedFunctionState&)>& states = {}) {
        effect.CurrentTechnique = effect.Techniques[technique];
        effect.CurrentTechnique->Passes[0].Apply();
        device.BlendState = BlendState::Opaque;
        device.DepthStencilState = DepthStencilState::None;
        device.RasterizerState = RasterizerState::CullNone;
        if (states) states(device.FixedFunction);
    }
    // The whole target, u = 0..1 left to right, v = 0..1 top to bottom, z from z0 to z1 left to right.
    void drawQuad(float z0, float z1) {
        const VertexPositionTexture v[6] = {{{-1, 1, z0}, {0, 0}}, {{1, 1, z1}, {1, 0}}, {{-1, -1, z0}, {0, 1}},
                                            {{1, 1, z1}, {1, 0}}, {{1, -1, z1}, {1, 1}}, {{-1, -1, z0}, {0, 1}}};
        device.DrawUserPrimitives(PrimitiveType::TriangleList, v, 0, 2);
    }
    void drawPoint(float size) {  // at the target's centre; `size` reaches PSIZE through u
        const VertexPositionTexture v[1] = {{{0, 0, 0.5f}, {size, 0}}};
        device.DrawUserPrimitives(PrimitiveType::PointList, v, 0, 1);
    }
    const float* pixel(const std::vector<float>& px, int x, int y) { return &px[std::size_t(y * kW + x) * 4]; }

    GraphicsDevice& device = testDevice();
    Effect effect{device, EffectSource{kSource, "FixedFunction.fx"}};
    RenderTarget2D target{device, kW, kH, false, SurfaceFormat::Vector4};
};

// D3D9 pixel i of a vs_3_0 draw is sampled at t = i / W across the target (its centre on the
// integer coordinate).
double sampleAt(int i, int size) { return double(i) / size; }

// The D3D9 fog blend of the blue, half-transparent shader colour toward `fog` by factor f.
void expectFogged(const float* got, double f, const Vector4& fog, const std::string& where) {
    f = std::clamp(f, 0.0, 1.0);
    const double want[4] = {fog.X * (1 - f), fog.Y * (1 - f), 1 * f + fog.Z * (1 - f), 0.5};
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[c], want[c], 2e-3) << where << " channel " << c << " f " << f;
}

TEST_F(FixedFunction, TableFogFollowsD3D9LinearExpAndExp2OfDepth) {
    const Vector4 fogColour(1, 0.5f, 0, 1);
    const double z0 = 0.1, z1 = 0.9;
    struct Case {
        FogMode mode;
        std::function<double(double)> f;
    } cases[] = {{FogMode::Linear, [](double d) { return (0.7 - d) / (0.7 - 0.2); }},
                 {FogMode::Exponential, [](double d) { return std::exp(-2.0 * d); }},
                 {FogMode::ExponentialSquared, [](double d) { return std::exp(-(1.5 * d) * (1.5 * d)); }}};
    for (const Case& c : cases) {
        device.Clear(Color(0, 0, 0, 0));
        apply("Fog", [&](FixedFunctionState& s) {
            s.FogEnable = true;
            s.FogTableMode = c.mode;
            s.FogColor = fogColour;
            s.FogStart = 0.2f, s.FogEnd = 0.7f, s.FogDensity = c.mode == FogMode::Exponential ? 2.0f : 1.5f;
        });
        drawQuad(float(z0), float(z1));
        std::vector<float> px = readFloats(target);
        for (int x = 0; x < kW; ++x) {
            const double d = z0 + (z1 - z0) * sampleAt(x, kW);
            expectFogged(pixel(px, x, kH / 2), c.f(d), fogColour, "mode " + std::to_string(int(c.mode)) + " x " + std::to_string(x));
        }
    }
}

TEST_F(FixedFunction, TableFogFromWUsesThePerspectiveCorrectEyeDepth) {
    const Vector4 fogColour(0, 1, 0, 1);
    const double w0 = 0.5, w1 = 2.0;
    effect.Parameters["W"].SetValue(Vector2(float(w0), float(w1)));
    apply("Fog", [&](FixedFunctionState& s) {
        s.FogEnable = true, s.FogTableMode = FogMode::Linear, s.FogFromW = true;
        s.FogColor = fogColour, s.FogStart = 0.25f, s.FogEnd = 2.25f;
    });
    drawQuad(0.5f, 0.5f);
    std::vector<float> px = readFloats(target);
    for (int x = 0; x < kW; ++x) {
        const double t = sampleAt(x, kW);
        const double w = 1.0 / ((1 - t) / w0 + t / w1);  // 1/w is linear on screen
        expectFogged(pixel(px, x, kH / 2), (2.25 - w) / 2.0, fogColour, "x " + std::to_string(x));
    }
}

TEST_F(FixedFunction, VertexFogTakesTheFogOutputElseSpecularAlpha) {
    const Vector4 fogColour(1, 0, 0, 1);
    for (const char* technique : {"Fog", "Specular"}) {
        device.Clear(Color(0, 0, 0, 0));
        apply(technique, [&](FixedFunctionState& s) {
            s.FogEnable = true, s.FogTableMode = FogMode::None, s.FogColor = fogColour;
            s.FogVertexMode = FogMode::Linear;  // ignored with a vertex shader, as in D3D9
        });
        drawQuad(0.5f, 0.5f);
        std::vector<float> px = readFloats(target);
        for (int x = 0; x < kW; ++x)
            expectFogged(pixel(px, x, kH / 2), sampleAt(x, kW), fogColour, std::string(technique) + " x " + std::to_string(x));
    }
}

TEST_F(FixedFunction, FogStartEqualToEndFogsEverything) {
    const Vector4 fogColour(0, 1, 1, 1);
    apply("Fog", [&](FixedFunctionState& s) {
        s.FogEnable = true, s.FogTableMode = FogMode::Linear, s.FogColor = fogColour, s.FogStart = s.FogEnd = 0.5f;
    });
    drawQuad(0.2f, 0.8f);
    std::vector<float> px = readFloats(target);
    for (int x = 0; x < kW; ++x) expectFogged(pixel(px, x, kH / 2), 0.0, fogColour, "x " + std::to_string(x));
}

// Pixels lit on the centre row and column of a point: its width and height.
std::pair<int, int> litExtent(const std::vector<float>& px, int w, int h) {
    int across = 0, down = 0;
    for (int x = 0; x < w; ++x) across += px[std::size_t((h / 2) * w + x) * 4 + 3] > 0 ? 1 : 0;
    for (int y = 0; y < h; ++y) down += px[std::size_t(y * w + w / 2) * 4 + 3] > 0 ? 1 : 0;
    return {across, down};
}

TEST_F(FixedFunction, PointSizeIsClampedToMinAndMaxAsD3D9Does) {
    RenderTarget2D big(device, 64, 64, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(big);
    // Odd sizes: a point's edges fall between pixel centres, so the count is the size exactly.
    struct Case { float size, min, max; const char* technique; } cases[] = {
        {9, 1, 64, "Sprite"}, {41, 1, 21, "Sprite"}, {3, 13, 64, "Sprite"},  // the device's PointSize
        {31, 1, 15, "ShaderSize"}, {5, 11, 64, "ShaderSize"}, {7, 1, 64, "ShaderSize"}};  // the shader's PSIZE
    for (const Case& c : cases) {
        device.Clear(Color(0, 0, 0, 0));
        const bool fromShader = std::string(c.technique) == "ShaderSize";
        apply(c.technique, [&](FixedFunctionState& s) {
            s.PointSize = fromShader ? 50 : c.size;  // ignored when the shader writes PSIZE
            s.PointSizeMin = c.min, s.PointSizeMax = c.max;
        });
        drawPoint(c.size);
        const int want = int(std::clamp(double(c.size), double(c.min), double(c.max)));
        auto [across, down] = litExtent(readFloats(big), 64, 64);
        EXPECT_EQ(across, want) << c.technique << " size " << c.size << " in [" << c.min << ", " << c.max << "]";
        EXPECT_EQ(down, want) << c.technique << " size " << c.size;
    }
}

TEST_F(FixedFunction, PointSpriteCoordinatesRunFromTopLeftToBottomRight) {
    RenderTarget2D big(device, 64, 64, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(big);
    const int size = 15;
    for (bool sprites : {false, true}) {
        device.Clear(Color(0, 0, 0, 0));
        apply("Sprite", [&](FixedFunctionState& s) { s.PointSize = float(size), s.PointSpriteEnable = sprites; });
        drawPoint(0.25f);
        std::vector<float> px = readFloats(big);
        // D3D9 puts the point's centre on pixel centre 32: it spans 24.5..39.5, covers pixels
        // 25..39, and pixel i (its centre at i, D3D9's rule) has the coordinate (i - 24.5) / 15.
        for (int y = 25; y <= 39; ++y)
            for (int x = 25; x <= 39; ++x) {
                const float* p = &px[std::size_t(y * 64 + x) * 4];
                const double u = sprites ? (x - 24.5) / size : 0.25, v = sprites ? (y - 24.5) / size : 0.0;
                EXPECT_NEAR(p[0], u, 1e-3) << "sprites " << sprites << " at " << x << "," << y;
                EXPECT_NEAR(p[1], v, 1e-3) << "sprites " << sprites << " at " << x << "," << y;
            }
        EXPECT_EQ(px[std::size_t(24 * 64 + 32) * 4 + 3], 0.0f) << "above the point";
        EXPECT_EQ(px[std::size_t(32 * 64 + 40) * 4 + 3], 0.0f) << "right of the point";
    }
}

TEST_F(FixedFunction, TrianglesIgnorePointSprites) {
    apply("Sprite", [&](FixedFunctionState& s) { s.PointSpriteEnable = true; });
    drawQuad(0.5f, 0.5f);
    std::vector<float> px = readFloats(target);
    for (int x = 0; x < kW; ++x) EXPECT_NEAR(pixel(px, x, kH / 2)[0], sampleAt(x, kW), 1e-3) << "x " << x;
}

TEST_F(FixedFunction, ClipPlanesKeepWhereDot4OfClipPositionIsNotNegative) {
    apply("Fog", [&](FixedFunctionState& s) {
        s.ClipPlaneEnable = 0b101;  // plane 1 would clip everything: it is off
        s.ClipPlanes[0] = Vector4(1, 1, 0, 0);
        s.ClipPlanes[1] = Vector4(0, 0, 0, -1);
        s.ClipPlanes[2] = Vector4(0, -1, 0, 0.5f);
    });
    drawQuad(0.5f, 0.5f);
    std::vector<float> px = readFloats(target);
    int kept = 0;
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const double nx = 2.0 * x / kW - 1, ny = 1 - 2.0 * y / kH;  // D3D9's sample point, NDC = clip (w = 1)
            const double d0 = nx + ny, d2 = 0.5 - ny;
            if (std::fabs(d0) < 0.2 || std::fabs(d2) < 0.2) continue;  // the edge pixels: either way
            const bool want = d0 >= 0 && d2 >= 0;
            kept += want;
            EXPECT_EQ(pixel(px, x, y)[3] > 0, want) << "pixel " << x << "," << y;
        }
    EXPECT_GT(kept, 20);
}

TEST_F(FixedFunction, AlphaTestComparesWithTheEightBitReference) {
    // Alpha runs 0..1 down the target; reference 0x180 is 0x80 (low 8 bits) = 128/255 = 0.50196.
    RenderTarget2D tall(device, 4, 256, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(tall);
    device.Clear(Color(0, 0, 0, 0));
    apply("AlphaRamp", [&](FixedFunctionState& s) {
        s.AlphaTestEnable = true, s.AlphaFunction = CompareFunction::Greater, s.ReferenceAlpha = 0x180;
    });
    drawQuad(0.5f, 0.5f);
    std::vector<float> px = readFloats(tall);
    for (int y = 0; y < 256; ++y) {
        const double alpha = sampleAt(y, 256);
        EXPECT_EQ(px[std::size_t(y * 4 + 1) * 4] > 0, alpha > 128.0 / 255.0) << "row " << y << " alpha " << alpha;
    }
}

TEST_F(FixedFunction, FlatShadingGivesColoursTheFirstVertexValue) {
    const VertexPositionColor v[3] = {{{-1, 3, 0.5f}, Color(255, 0, 0, 255)}, {{3, -1, 0.5f}, Color(0, 255, 0, 255)},
                                      {{-1, -1, 0.5f}, Color(0, 0, 255, 255)}};
    for (bool flat : {true, false}) {
        device.Clear(Color(0, 0, 0, 0));
        apply("Colours", [&](FixedFunctionState& s) { s.ShadeMode = flat ? ShadeMode::Flat : ShadeMode::Gouraud; });
        device.DrawUserPrimitives(PrimitiveType::TriangleList, v, 0, 1);
        std::vector<float> px = readFloats(target);
        int first = 0;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                const float* p = pixel(px, x, y);
                first += p[0] == 1.0f && p[1] == 0.0f && p[2] == 0.0f;
            }
        if (flat) EXPECT_EQ(first, kW * kH);
        else EXPECT_LT(first, kW * kH / 4);
    }
}

TEST_F(FixedFunction, PassStatesSetTheDeviceStatesAtApply) {
    apply("PassFog");
    EXPECT_TRUE(device.FixedFunction.FogEnable);
    EXPECT_EQ(device.FixedFunction.FogTableMode, FogMode::Linear);
    EXPECT_EQ(device.FixedFunction.FogColor, Vector4(0, 1, 0, 1));
    drawQuad(0.1f, 0.9f);
    std::vector<float> px = readFloats(target);
    for (int x = 0; x < kW; ++x) {
        const double d = 0.1 + 0.8 * sampleAt(x, kW);
        expectFogged(pixel(px, x, kH / 2), (0.75 - d) / 0.5, Vector4(0, 1, 0, 1), "x " + std::to_string(x));
    }

    apply("PassPoints");
    const FixedFunctionState& s = device.FixedFunction;
    EXPECT_FALSE(s.FogEnable) << "the next pass starts from D3D9's defaults";
    EXPECT_EQ(s.PointSize, 9.0f);
    EXPECT_EQ(s.PointSizeMin, 2.0f);
    EXPECT_EQ(s.PointSizeMax, 30.0f);
    EXPECT_TRUE(s.PointSpriteEnable);
    EXPECT_EQ(s.ClipPlaneEnable, 5u);
    EXPECT_EQ(s.ClipPlanes[0], Vector4(1, 0, 0, 0.5f));
    EXPECT_EQ(s.ClipPlanes[2], Vector4(0, 1, 0, 0));
    EXPECT_EQ(s.ShadeMode, ShadeMode::Flat);
    EXPECT_TRUE(s.AlphaTestEnable);
    EXPECT_EQ(s.AlphaFunction, CompareFunction::Greater);
    EXPECT_EQ(s.ReferenceAlpha & 0xFF, 0x80);

    effect.CurrentTechnique = effect.Techniques["Fog"];
    effect.CurrentTechnique->Passes[0].Apply();
    EXPECT_EQ(device.FixedFunction, FixedFunctionState{}) << "a pass without them turns them off";
}

}  // namespace
}  // namespace fxport
