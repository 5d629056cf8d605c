// Lazy effects: loading parses an effect; a technique's shaders are compiled at the first Apply of
// one of its passes. Parameters set before that take effect, and Apply uploads only the constants
// the bound shaders read. Expected colours are computed here from the values set.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>

#include "fxport/xlate/compiled_effect.h"
#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::drawQuad;
using test::readFloats;
using test::testDevice;

// Two techniques sharing a vertex shader. $Global holds the transform and both colours (each
// technique's pixel shader reads one of them), far apart so their byte ranges do not touch; the
// user cbuffer `Material` is read only by technique B, so its layout is learnt only when B
// compiles. Material packs a float after a float3 and an array of float2, which the provisional
// layout stores differently from HLSL packing.
const char* kTwoTechniques = R"(
float4x4 Transform;
float4 ColorA;
float4 Spacer[8];
float4 ColorB;
cbuffer Material {
    float3 Tint;
    float Scale;
    float2 Offsets[3];
};
float4 VS(float4 position : POSITION0) : POSITION0 { return mul(position, Transform); }
float4 PSA() : COLOR0 { return ColorA; }
float4 PSB() : COLOR0 { return float4(ColorB.rgb * Tint * Scale, Offsets[2].y + ColorB.a); }
technique A { pass P0 { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PSA(); } }
technique B { pass P0 { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PSB(); } }
)";

class LazyEffect : public ::testing::Test {
protected:
    void SetUp() override {
        device.BlendState = BlendState::Opaque;
        device.DepthStencilState = DepthStencilState::None;
        device.RasterizerState = RasterizerState::CullNone;
        dir = std::filesystem::temp_directory_path() /
              ("fxport_lazy_" + std::to_string(std::chrono::steady_clock::now().time_since_epoch().count()));
        std::filesystem::create_directories(dir);
        path = (dir / "TwoTechniques.fx").string();
        std::ofstream(path) << kTwoTechniques;
        options.cacheDir = (dir / "cache").string();  // cold: nothing compiled before this test
    }
    void TearDown() override {
        device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        std::error_code ec;
        std::filesystem::remove_all(dir, ec);
    }
    // Draws the full-screen quad with `technique` into a 4x2 target and returns its pixels.
    std::vector<float> render(Effect& effect, const std::string& technique) {
        RenderTarget2D target(device, 4, 2, false, SurfaceFormat::Vector4);
        device.SetRenderTarget(target);
        device.Clear(Color::Transparent);
        effect.CurrentTechnique = effect.Techniques[technique];
        effect.CurrentTechnique->Passes[0].Apply();
        drawQuad(device);
        std::vector<float> px = readFloats(target);
        device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        return px;
    }
    static void expectAll(const std::vector<float>& px, Vector4 want, const std::string& what) {
        for (std::size_t i = 0; i < px.size() / 4; ++i) {
            EXPECT_NEAR(px[i * 4 + 0], want.X, 1e-6) << what << " texel " << i;
            EXPECT_NEAR(px[i * 4 + 1], want.Y, 1e-6) << what << " texel " << i;
            EXPECT_NEAR(px[i * 4 + 2], want.Z, 1e-6) << what << " texel " << i;
            EXPECT_NEAR(px[i * 4 + 3], want.W, 1e-6) << what << " texel " << i;
        }
    }
    void setMaterial(Effect& effect, Vector3 tint, float scale, const std::vector<Vector2>& offsets) {
        effect.Parameters["Tint"].SetValue(tint);
        effect.Parameters["Scale"].SetValue(scale);
        effect.Parameters["Offsets"].SetValue(offsets);
    }

    GraphicsDevice& device = testDevice();
    std::filesystem::path dir;
    std::string path;
    EffectOptions options;
};

TEST_F(LazyEffect, CompilesOnlyTheAppliedTechniqueAndParametersSetBeforeTakeEffect) {
    Effect effect(device, path, options);
    // Known right after load, nothing compiled.
    ASSERT_EQ(effect.Techniques.Count(), 2);
    EXPECT_EQ(effect.Parameters.Count(), 7);
    EXPECT_FALSE(effect.Techniques["A"]->IsCompiled());
    EXPECT_FALSE(effect.Techniques["B"]->IsCompiled());
    EffectStatistics loaded = effect.statistics();
    EXPECT_TRUE(loaded.compiledTechniques.empty());
    EXPECT_EQ(loaded.techniqueCount, 2);
    EXPECT_EQ(loaded.compileMilliseconds, 0.0);

    // Every parameter is settable (and reads back) before any shader exists.
    effect.Parameters["Transform"].SetValue(Matrix::Identity);
    effect.Parameters["ColorA"].SetValue(Vector4(0.25f, 0.5f, 0.75f, 1.0f));
    effect.Parameters["ColorB"].SetValue(Vector4(0.5f, 0.5f, 1.0f, 0.125f));
    setMaterial(effect, Vector3(1.0f, 0.5f, 0.25f), 2.0f, {Vector2(9, 9), Vector2(8, 8), Vector2(7, 0.5f)});
    EXPECT_EQ(effect.Parameters["ColorA"].GetValueVector4(), Vector4(0.25f, 0.5f, 0.75f, 1.0f));
    EXPECT_EQ(effect.Parameters["Scale"].GetValueSingle(), 2.0f);

    expectAll(render(effect, "A"), Vector4(0.25f, 0.5f, 0.75f, 1.0f), "technique A");
    EffectStatistics afterA = effect.statistics();
    EXPECT_EQ(afterA.compiledTechniques, std::vector<std::string>{"A"});
    EXPECT_TRUE(effect.Techniques["A"]->IsCompiled());
    EXPECT_FALSE(effect.Techniques["B"]->IsCompiled());
    EXPECT_GT(afterA.compileMilliseconds, 0.0);
    // Material is not read by A: its values are still in the provisional layout, unchanged.
    EXPECT_EQ(effect.Parameters["Tint"].GetValueVector3(), Vector3(1.0f, 0.5f, 0.25f));
    EXPECT_EQ(effect.Parameters["Offsets"].GetValueSingleArray(), (std::vector<float>{9, 9, 8, 8, 7, 0.5f}));

    // B compiles on its first Apply and sees everything set before (colour * tint * scale).
    expectAll(render(effect, "B"), Vector4(0.5f * 1.0f * 2.0f, 0.5f * 0.5f * 2.0f, 1.0f * 0.25f * 2.0f, 0.5f + 0.125f),
              "technique B");
    EffectStatistics afterB = effect.statistics();
    EXPECT_EQ(afterB.compiledTechniques, (std::vector<std::string>{"A", "B"}));
    EXPECT_GT(afterB.compileMilliseconds, afterA.compileMilliseconds);
    EXPECT_EQ(effect.Parameters["Offsets"].GetValueSingleArray(), (std::vector<float>{9, 9, 8, 8, 7, 0.5f}));

    // Back to A, then B again with new material values: both still right.
    expectAll(render(effect, "A"), Vector4(0.25f, 0.5f, 0.75f, 1.0f), "technique A again");
    setMaterial(effect, Vector3(0.5f, 0.5f, 0.5f), 1.0f, {Vector2(0, 0), Vector2(0, 0), Vector2(0, 0.25f)});
    expectAll(render(effect, "B"), Vector4(0.25f, 0.25f, 0.5f, 0.375f), "technique B with a new material");
}

// A matrix set before compiling lands where the compiled layout (column_major) puts it: the quad
// moved right by one NDC unit leaves the left half of the target clear.
TEST_F(LazyEffect, MatrixSetBeforeCompileKeepsItsMeaning) {
    Effect effect(device, path, options);
    effect.Parameters["Transform"].SetValue(Matrix::CreateTranslation(1, 0, 0));
    effect.Parameters["ColorA"].SetValue(Vector4(1, 1, 1, 1));
    std::vector<float> px = render(effect, "A");
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x)
            EXPECT_EQ(px[std::size_t(y * 4 + x) * 4 + 3], x < 2 ? 0.0f : 1.0f) << "pixel " << x << "," << y;
    EXPECT_EQ(effect.Parameters["Transform"].GetValueMatrix(), Matrix::CreateTranslation(1, 0, 0));
}

TEST_F(LazyEffect, ApplyUploadsOnlyTheConstantsItsShadersRead) {
    Effect effect(device, path, options);
    effect.Parameters["Transform"].SetValue(Matrix::Identity);
    effect.Parameters["ColorA"].SetValue(Vector4(0.25f, 0.25f, 0.25f, 1));
    effect.Parameters["ColorB"].SetValue(Vector4(1, 1, 1, 1));
    setMaterial(effect, Vector3(1, 1, 1), 0.5f, {Vector2(0, 0), Vector2(0, 0), Vector2(0, 0)});
    render(effect, "A");
    render(effect, "B");  // everything uploaded once

    // ColorB changes; A does not read it: applying A sends nothing and draws as before.
    effect.Parameters["ColorB"].SetValue(Vector4(0.5f, 1, 1, 0.75f));
    std::uint64_t before = effect.statistics().constantBytesUploaded;
    expectAll(render(effect, "A"), Vector4(0.25f, 0.25f, 0.25f, 1), "A after ColorB changed");
    EXPECT_EQ(effect.statistics().constantBytesUploaded, before) << "A uploaded something it does not read";

    // B reads it: exactly its 16 bytes go up, and B draws the new value.
    expectAll(render(effect, "B"), Vector4(0.25f, 0.5f, 0.5f, 0.75f), "B after ColorB changed");
    EXPECT_EQ(effect.statistics().constantBytesUploaded, before + 16);

    // Nothing changed: nothing sent.
    before = effect.statistics().constantBytesUploaded;
    render(effect, "B");
    render(effect, "A");
    EXPECT_EQ(effect.statistics().constantBytesUploaded, before);

    // Both colours change; A sends ColorA only and leaves ColorB pending for B.
    effect.Parameters["ColorA"].SetValue(Vector4(0.75f, 0.75f, 0.75f, 1));
    effect.Parameters["ColorB"].SetValue(Vector4(1, 1, 1, 0.5f));
    before = effect.statistics().constantBytesUploaded;
    expectAll(render(effect, "A"), Vector4(0.75f, 0.75f, 0.75f, 1), "A after both changed");
    EXPECT_EQ(effect.statistics().constantBytesUploaded, before + 16);
    expectAll(render(effect, "B"), Vector4(0.5f, 0.5f, 0.5f, 0.5f), "B after both changed");
    EXPECT_EQ(effect.statistics().constantBytesUploaded, before + 32);
}

TEST_F(LazyEffect, PrecompileCompilesEverythingUpFront) {
    EffectOptions eager = options;
    eager.precompile = true;
    Effect effect(device, path, eager);
    EXPECT_TRUE(effect.Techniques["A"]->IsCompiled());
    EXPECT_TRUE(effect.Techniques["B"]->IsCompiled());
    EXPECT_EQ(effect.statistics().compileMilliseconds, 0.0);  // all of it happened at load
    EXPECT_GT(effect.statistics().loadMilliseconds, 0.0);
    effect.Parameters["Transform"].SetValue(Matrix::Identity);
    effect.Parameters["ColorA"].SetValue(Vector4(0, 1, 0, 1));
    expectAll(render(effect, "A"), Vector4(0, 1, 0, 1), "precompiled A");

    Effect lazy(device, path, options);
    lazy.Precompile();
    EXPECT_EQ(lazy.statistics().compiledTechniques, (std::vector<std::string>{"A", "B"}));
    // compiled() is the whole effect, with the GLSL of every shader.
    const xlate::CompiledEffect& whole = lazy.compiled();
    EXPECT_EQ(whole.techniques.size(), 2u);
    EXPECT_EQ(whole.shaders.size(), 3u);  // VS, PSA, PSB
    for (const xlate::CompiledShader& s : whole.shaders) EXPECT_FALSE(s.glsl.empty()) << s.entryPoint;
}

// D3D9: a pass without a vertex shader keeps the one bound. When that is the effect's own (from
// pass 0), a constant it reads that changed before pass 1's Apply must still reach it, although
// pass 1's own shader does not read it.
TEST_F(LazyEffect, KeptVertexShaderSeesConstantsChangedBeforeAPixelOnlyPass) {
    std::string twoPasses = (dir / "TwoPasses.fx").string();
    std::ofstream(twoPasses) << "float4x4 Transform;\n"
                                "float4 Color;\n"
                                "float4 VS(float4 p : POSITION0) : POSITION0 { return mul(p, Transform); }\n"
                                "float4 PS() : COLOR0 { return Color; }\n"
                                "technique T {\n"
                                "  pass Full { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); }\n"
                                "  pass PixelOnly { PixelShader = compile ps_3_0 PS(); }\n"
                                "}\n";
    Effect effect(device, twoPasses, options);
    RenderTarget2D target(device, 4, 2, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.Clear(Color::Transparent);
    effect.Parameters["Transform"].SetValue(Matrix::Identity);
    effect.Parameters["Color"].SetValue(Vector4(1, 1, 1, 1));
    effect.CurrentTechnique->Passes["Full"].Apply();
    effect.Parameters["Transform"].SetValue(Matrix::CreateTranslation(1, 0, 0));  // right half only
    effect.CurrentTechnique->Passes["PixelOnly"].Apply();
    drawQuad(device);
    std::vector<float> px = readFloats(target);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 4; ++x)
            EXPECT_EQ(px[std::size_t(y * 4 + x) * 4 + 3], x < 2 ? 0.0f : 1.0f) << "pixel " << x << "," << y;
}

// An HLSL error that only glslang finds (an unknown variable inside a function) surfaces when a
// technique is first applied, naming the file and line; loading parsed the effect without error.
// (glslang compiles the whole source for every shader, so the error fails any technique.)
TEST_F(LazyEffect, ShaderErrorSurfacesAtFirstApply) {
    std::string broken = (dir / "Broken.fx").string();
    std::ofstream(broken) << "float4 Color;\n"
                             "float4 VS(float4 p : POSITION0) : POSITION0 { return p; }\n"
                             "float4 Good() : COLOR0 { return Color; }\n"
                             "float4 Bad() : COLOR0 { return Color * undefinedThing; }\n"
                             "technique Fails { pass P0 { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 Bad(); } }\n";
    std::unique_ptr<Effect> effect;
    ASSERT_NO_THROW(effect = std::make_unique<Effect>(device, broken, options));
    effect->Parameters["Color"].SetValue(Vector4(1, 0, 1, 1));
    try {
        render(*effect, "Fails");
        ADD_FAILURE() << "applying the broken technique did not throw";
    } catch (const xlate::CompileError& e) {
        std::string message = e.what();
        EXPECT_NE(message.find("Broken.fx(4,"), std::string::npos) << message;
        EXPECT_NE(message.find("undefinedThing"), std::string::npos) << message;
    }
    EXPECT_FALSE(effect->Techniques["Fails"]->IsCompiled());
    // Still a usable object: applying again reports the same error instead of crashing.
    EXPECT_THROW(effect->CurrentTechnique->Passes[0].Apply(), xlate::CompileError);
}

}  // namespace
}  // namespace fxport
