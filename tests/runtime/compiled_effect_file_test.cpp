// Effect::FromCompiledFile: an effect compiled ahead of time (fxport compile, fxport_add_effects)
// loads and draws with its source gone and without any compile at run time.
#include <gtest/gtest.h>

#include <filesystem>

#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"
#include "runtime_test_support.h"

namespace fxport {
namespace {

namespace fs = std::filesystem;

TEST(CompiledEffectFile, LoadsAndDrawsWithoutItsSourceAndWithoutCompiling) {
    GraphicsDevice& device = test::testDevice();
    fs::path dir = fs::path(::testing::TempDir()) / "fxport_compiled_effect_file";
    fs::create_directories(dir);
    fs::path source = dir / "Conventions.fx", compiled = dir / "Conventions.fxeffect";
    fs::copy_file(test::runtimeFixture("Conventions.fx"), source, fs::copy_options::overwrite_existing);
    xlate::CompileOptions options;
    options.useCache = false;
    xlate::saveEffectFile(xlate::compileEffectFile(source.string(), options), compiled.string());
    fs::remove(source);  // nothing can compile it again

    std::unique_ptr<Effect> effect = Effect::FromCompiledFile(device, compiled.string());
    for (int t = 0; t < effect->Techniques.Count(); ++t)
        EXPECT_TRUE(effect->Techniques[t]->IsCompiled()) << effect->Techniques[t]->Name() << " would compile at its first Apply";
    RenderTarget2D target(device, 2, 2, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.BlendState = BlendState::Opaque;
    device.RasterizerState = RasterizerState::CullNone;
    device.DepthStencilState = DepthStencilState::None;
    effect->CurrentTechnique = effect->Techniques["SolidColor"];
    effect->Parameters["Color"].SetValue(Vector4(0.75f, 0.5f, 0.25f, 1));
    effect->CurrentTechnique->Passes[0].Apply();
    test::drawQuad(device);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    std::vector<float> px = test::readFloats(target);
    EXPECT_EQ(px[0], 0.75f);
    EXPECT_EQ(px[1], 0.5f);
    EXPECT_EQ(px[2], 0.25f);
    EXPECT_EQ(effect->statistics().compileMilliseconds, 0.0);  // no xlate compile after load
}

}  // namespace
}  // namespace fxport
