// Issue 24 item 1: NVIDIA's FXAA 3.11 header compiled by fxport under FXAA_HLSL_3, _4 and _5
// (FXAA_PC 1, quality preset 12) renders an aliased test image as a CPU port of FXAA's PC quality
// path computes it (fxaa_reference.cpp; docs/fxaa-check.md). The header is NVIDIA's and is not in
// this repository: the test reads it from $FXPORT_FXAA_HEADER and skips when that is unset.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "fxaa_reference.h"
#include "runtime_test_support.h"

namespace fxport {
namespace {

namespace fs = std::filesystem;

// A small effect around FxaaPixelShader for one HLSL path. D3D9 samples at integer pixel
// coordinates, so the HLSL_3 shader moves its coordinate to the texel centre as D3D9 ports do.
std::string effectSource(int hlsl, const std::string& header) {
    std::string s = "#define FXAA_PC 1\n#define FXAA_HLSL_" + std::to_string(hlsl) +
                    " 1\n#define FXAA_QUALITY__PRESET 12\n#define FXAA_GREEN_AS_LUMA 0\n#include \"" + header + "\"\n"
                    "float2 Rcp;\n";
    if (hlsl == 3) {
        s += "texture SceneTex;\n"
             "sampler SceneSampler = sampler_state { Texture = <SceneTex>; MinFilter = Linear; MagFilter = Linear;"
             " MipFilter = None; AddressU = Clamp; AddressV = Clamp; };\n"
             "void VS(float4 p : POSITION0, float2 uv : TEXCOORD0, out float4 op : POSITION0, out float2 ouv : TEXCOORD0)"
             " { op = p; ouv = uv; }\n"
             "float4 PS(float2 uv : TEXCOORD0) : COLOR0 {\n"
             "    FxaaTex t = SceneSampler;\n"
             "    uv += 0.5 * Rcp;\n";
    } else {
        s += "Texture2D SceneTex;\n"
             "SamplerState SceneSampler { Filter = MIN_MAG_MIP_LINEAR; AddressU = Clamp; AddressV = Clamp; };\n"
             "void VS(float4 p : POSITION0, float2 uv : TEXCOORD0, out float4 op : SV_Position, out float2 ouv : TEXCOORD0)"
             " { op = p; ouv = uv; }\n"
             "float4 PS(float4 pos : SV_Position, float2 uv : TEXCOORD0) : SV_Target {\n"
             "    FxaaTex t = { SceneSampler, SceneTex };\n";
    }
    s += "    return FxaaPixelShader(uv, 0, t, t, t, Rcp, 0, 0, 0, 0.75, 0.166, 0.0833, 8.0, 0.125, 0.05, 0);\n}\n";
    if (hlsl == 3)
        s += "technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }\n";
    else
        s += "technique11 T { pass P { SetVertexShader(CompileShader(vs_" + std::to_string(hlsl) + "_0, VS()));"
             " SetPixelShader(CompileShader(ps_" + std::to_string(hlsl) + "_0, PS())); } }\n";
    return s;
}

// Hard-edged shapes FXAA has to work on: a shallow and a steep edge, a one-texel line, a lone
// texel, on a coloured background; luma (gamma-space, as FXAA wants it) in alpha.
std::vector<Color> aliasedImage(int n) {
    std::vector<Color> image(std::size_t(n * n));
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            Color c(40, 60, 110, 255);
            if (3 * y < x + 20) c = Color(230, 210, 120, 255);                       // shallow edge
            if (x > 36 && y > 2 * (x - 36) + 10) c = Color(200, 40, 40, 255);         // steep edge
            if (y == 48 && x > 4 && x < 30) c = Color(250, 250, 250, 255);            // thin line
            if (x == 10 && y == 36) c = Color(255, 255, 255, 255);                    // lone texel
            // A little per-texel variation, so that no two neighbourhoods tie exactly on FXAA's
            // thresholds (where the GPU's and the CPU's last-bit rounding would pick differently).
            const unsigned hash = unsigned(x) * 73856093u ^ unsigned(y) * 19349663u;
            auto vary = [&](std::uint8_t v, int k) { return std::uint8_t(std::clamp(int(v) + int((hash >> (4 * k)) % 13) - 6, 0, 255)); };
            c = Color(vary(c.R, 0), vary(c.G, 1), vary(c.B, 2), 255);
            const double luma = (0.299 * c.R + 0.587 * c.G + 0.114 * c.B) / 255.0;
            c.A = std::uint8_t(std::lround(std::sqrt(luma) * 255));
            image[std::size_t(y * n + x)] = c;
        }
    }
    return image;
}

// Channels CPU FXAA changes by more than 1e-4.
int changedByCpu(const test::FxaaImage& image, float centreOffset) {
    test::FxaaSettings settings;
    settings.centreOffset = centreOffset;
    int changed = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const auto out = test::fxaaPixel(image, x, y, settings);
            for (int k = 0; k < 3; ++k)
                changed += std::abs(out[std::size_t(k)] - image.texels[std::size_t(y * image.width + x)][std::size_t(k)]) > 1e-4f ? 1 : 0;
        }
    return changed;
}

struct Comparison {
    double maxError = 0, meanError = 0;
    int worst = 0, over = 0, tieTaken = 0;
};

// The GPU's pixels against CPU FXAA: FXAA as written (tie bias 0), or, where one of its decisions
// ties exactly (within 1e-5) and the GPU's last-bit rounding broke the tie the other way, FXAA
// with that tie broken so -- whichever of the three is nearer to the GPU's pixel.
Comparison compare(const std::vector<float>& got, const test::FxaaImage& image, float centreOffset) {
    const int n = image.width;
    Comparison c;
    double sum = 0;
    for (int i = 0; i < n * n; ++i) {
        double bestError = 1e9;
        std::array<float, 4> best{};
        int bestVariant = 0;
        for (int v = 0; v < 3; ++v) {
            test::FxaaSettings settings;
            settings.centreOffset = centreOffset;
            settings.tieBias = v == 0 ? 0.0f : v == 1 ? -1e-5f : 1e-5f;
            const auto want = test::fxaaPixel(image, i % n, i / n, settings);
            double e = 0;
            for (int k = 0; k < 4; ++k) e = std::max(e, std::abs(double(got[std::size_t(i * 4 + k)]) - want[std::size_t(k)]));
            if (e < bestError - 1e-9) bestError = e, best = want, bestVariant = v;
        }
        c.tieTaken += bestVariant != 0 ? 1 : 0;
        for (int k = 0; k < 4; ++k) {
            const double e = std::abs(double(got[std::size_t(i * 4 + k)]) - best[std::size_t(k)]);
            sum += e;
            if (e > c.maxError) c.maxError = e, c.worst = i;
            c.over += e > 2.0 / 255 ? 1 : 0;
            if (e > 2.0 / 255 && std::getenv("FXAA_DEBUG"))
                std::printf("  (%d,%d).%d gpu %.4f cpu %.4f src %.4f\n", i % n, i / n, k, got[std::size_t(i * 4 + k)], best[std::size_t(k)],
                            image.texels[std::size_t(i)][std::size_t(k)]);
        }
    }
    c.meanError = sum / (n * n * 4);
    return c;
}

TEST(Fxaa311, HeaderRendersAsCpuFxaa) {
    const char* headerEnv = std::getenv("FXPORT_FXAA_HEADER");
    if (!headerEnv || !*headerEnv) GTEST_SKIP() << "FXPORT_FXAA_HEADER is not set (the path of NVIDIA's Fxaa3_11.fxh)";
    const fs::path header(headerEnv);
    ASSERT_TRUE(fs::is_regular_file(header)) << "FXPORT_FXAA_HEADER=" << header << " is not a file";

    const int n = 64;  // a power of two: texel centres and FXAA's half-texel steps are exact floats
    const std::vector<Color> image = aliasedImage(n);
    test::FxaaImage cpuImage{n, n, {}};
    for (const Color& c : image) cpuImage.texels.push_back({c.R / 255.0f, c.G / 255.0f, c.B / 255.0f, c.A / 255.0f});
    ASSERT_GT(changedByCpu(cpuImage, 0), 50) << "the test image gives FXAA too little to do";
    GraphicsDevice& device = test::testDevice();
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::None;
    device.RasterizerState = RasterizerState::CullNone;
    Texture2D texture(device, n, n, false, SurfaceFormat::Color);
    texture.SetData(image);
    for (int hlsl : {3, 4, 5}) {
        SCOPED_TRACE("FXAA_HLSL_" + std::to_string(hlsl));
        EffectOptions options;
        options.useCache = false;
        options.includeDirs = {header.parent_path().string()};
        Effect effect(device, EffectSource{effectSource(hlsl, header.filename().string()), "fxaa_check_hlsl" + std::to_string(hlsl) + ".fx"},
                      options);
        effect.Parameters["SceneTex"].SetValue(texture);
        effect.Parameters["Rcp"].SetValue(Vector2(1.0f / n, 1.0f / n));
        RenderTarget2D target(device, n, n, false, SurfaceFormat::Vector4);
        device.SetRenderTarget(target);
        device.Clear(Color::Black);
        effect.CurrentTechnique->Passes[0].Apply();
        test::drawQuad(device);
        device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        const std::vector<float> got = test::readFloats(target);

        // The D3D9 path is checked at the coordinates fxport gives it (texel centre + 1/256 texel) and,
        // for the record, against FXAA at the exact centres.
        const Comparison exact = compare(got, cpuImage, 0);
        const Comparison asDrawn = hlsl == 3 ? compare(got, cpuImage, 1.0f / 256) : exact;
        std::printf("FXAA_HLSL_%d: %d channels changed by CPU FXAA; GPU vs CPU at texel centres: max error %.6f (%.3f/255) at (%d, %d), "
                    "mean %.2e, %d channels over 2/255, %d pixels matched a tie broken the other way\n",
                    hlsl, changedByCpu(cpuImage, 0), exact.maxError, exact.maxError * 255, exact.worst % n, exact.worst / n, exact.meanError,
                    exact.over, exact.tieTaken);
        if (hlsl == 3)
            std::printf("FXAA_HLSL_3 at fxport's D3D9 coordinates (centre + 1/256 texel): max error %.6f (%.3f/255) at (%d, %d), mean %.2e, "
                        "%d channels over 2/255, %d pixels matched a tie broken the other way\n",
                        asDrawn.maxError, asDrawn.maxError * 255, asDrawn.worst % n, asDrawn.worst / n, asDrawn.meanError, asDrawn.over,
                        asDrawn.tieTaken);
        const double maxError = asDrawn.maxError;
        const int worst = asDrawn.worst;
        EXPECT_LE(maxError, 2.0 / 255) << "worst texel (" << worst % n << ", " << worst / n << ")";
    }
}

}  // namespace
}  // namespace fxport
