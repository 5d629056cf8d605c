// The GPU-limits probe and the fragment counts a pass's bound is made of (issue 16): the probe
// measures positive, finite rates, leaves the device drawing as before, and its cache holds what it
// wrote; GpuTimer's fragment counts are the exact number of pixels a draw covered; the device's
// fragment tally splits them by the pixel shader's texture fetches, and targetsWrittenSinceMark lists
// only what draws and clears wrote (issue 16 item 2's per-pass bounds).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "fxport/graphics/gpu_limits.h"
#include "fxport/graphics/gpu_timer.h"
#include "fxport/platform/gl.h"
#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::drawQuad;
using test::readFloats;
using test::runtimeFixture;

struct Device {
    Device() {
        PresentationParameters p;
        p.BackBufferWidth = 8;
        p.BackBufferHeight = 4;
        // These tests count the fragments the rasteriser produced: no draw may run as a compute pass
        // (on by default on a GPU like the H100).
        p.Optimizations.ComputePasses = false;
        device = std::make_unique<GraphicsDevice>(p);
        effect = std::make_unique<Effect>(*device, runtimeFixture("Conventions.fx"));
        effect->CurrentTechnique = effect->Techniques["SolidColor"];
        device->RasterizerState = RasterizerState::CullNone;
        device->DepthStencilState = DepthStencilState::None;
    }
    void draw(Vector4 color) {
        effect->Parameters["Color"].SetValue(color);
        effect->CurrentTechnique->Passes[0].Apply();
        drawQuad(*device);
    }
    std::unique_ptr<GraphicsDevice> device;
    std::unique_ptr<Effect> effect;
};

bool positive(double v) { return std::isfinite(v) && v > 0; }

TEST(GpuLimits, MeasuresEveryRateAndLeavesTheDeviceDrawingAsBefore) {
    Device d;
    RenderTarget2D target(*d.device, 8, 4, false, SurfaceFormat::Vector4, DepthFormat::None);
    d.device->SetRenderTarget(target);
    d.device->Clear(Color(0, 0, 0, 0));
    d.device->BlendState = BlendState::Additive;
    d.draw(Vector4(0.25f, 0, 0, 1));  // the device's GL state is set up before the probe
    GpuLimits limits = GpuLimits::Measure(*d.device, 64, 1);
    EXPECT_EQ(limits.renderer, d.device->rendererName());
    ASSERT_EQ(limits.fill.size(), 6u);
    for (const GpuLimits::Fill& f : limits.fill) {
        EXPECT_TRUE(positive(f.opaqueGBps)) << surfaceFormatName(f.format);
        EXPECT_TRUE(positive(f.blendedGBps)) << surfaceFormatName(f.format);
    }
    EXPECT_TRUE(positive(limits.clearGBps));
    EXPECT_TRUE(positive(limits.fetchGTexelsPerSecond));
    EXPECT_TRUE(positive(limits.computeWriteGBps));
    // Still additive, into the same target: 0.25 + 0.5 (the probe's blending and targets are gone).
    d.draw(Vector4(0.5f, 0, 0, 1));
    d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    std::vector<float> texels = readFloats(target);
    for (int i = 0; i < 32; ++i) EXPECT_FLOAT_EQ(texels[std::size_t(i) * 4], 0.75f) << "texel " << i;
}

TEST(GpuLimits, TextRoundTripsAndUnknownFormatsTakeTheirTexelSizesRate) {
    GpuLimits limits;
    limits.renderer = "Some GPU / 4.5";
    const SurfaceFormat formats[] = {SurfaceFormat::Color,  SurfaceFormat::Rgba64, SurfaceFormat::HalfVector4,
                                     SurfaceFormat::Vector4, SurfaceFormat::Single, SurfaceFormat::Vector2};
    double rate = 10;
    for (SurfaceFormat f : formats) limits.fill.push_back({f, rate, rate / 2}), rate += 10;
    limits.clearGBps = 50;
    limits.fetchGTexelsPerSecond = 30;
    limits.computeWriteGBps = 70;
    GpuLimits back;
    ASSERT_TRUE(GpuLimits::fromText(limits.toText(), back));
    EXPECT_EQ(back.renderer, limits.renderer);
    EXPECT_EQ(back.toText(), limits.toText());
    EXPECT_DOUBLE_EQ(back.fillGBps(SurfaceFormat::Vector4, false), 40);
    EXPECT_DOUBLE_EQ(back.fillGBps(SurfaceFormat::Vector4, true), 20);
    // HdrBlendable (8 bytes) is not measured: Rgba64's, the first measured 8-byte format.
    EXPECT_DOUBLE_EQ(back.fillGBps(SurfaceFormat::HdrBlendable, false), 20);
    // Bgr565 (2 bytes) has no measured size: the slowest.
    EXPECT_DOUBLE_EQ(back.fillGBps(SurfaceFormat::Bgr565, false), 10);
    GpuLimits untouched;
    EXPECT_FALSE(GpuLimits::fromText("renderer x\nfill Color 1 1\n", untouched));         // formats missing
    EXPECT_FALSE(GpuLimits::fromText(limits.toText() + "speed 3\n", untouched));         // unknown key
    EXPECT_FALSE(GpuLimits::fromText("fill Color -1 1\n" + limits.toText(), untouched));  // not a rate
    // A cache from before the compute write rate was probed is measured again.
    std::string withoutCompute = limits.toText();
    withoutCompute.erase(withoutCompute.find("compute "));
    EXPECT_FALSE(GpuLimits::fromText(withoutCompute, untouched));
    EXPECT_TRUE(untouched.fill.empty());
}

// DeviceOptimizations::ComputePasses' default: on only where compute image writes are at least
// kComputePassesWhereFaster times the fragment stage's Color output (the H100: 393.8 against 56.3).
TEST(GpuLimits, ComputePassesAreTheDefaultOnlyWhereComputeWritesAreFaster) {
    GpuLimits limits;
    limits.fill.push_back({SurfaceFormat::Color, 56.3, 63.3});
    limits.computeWriteGBps = 393.8;
    EXPECT_TRUE(limits.computePassesFaster());
    limits.computeWriteGBps = 56.3 * kComputePassesWhereFaster * 0.99;
    EXPECT_FALSE(limits.computePassesFaster());
    limits.computeWriteGBps = 56.3 * kComputePassesWhereFaster;
    EXPECT_TRUE(limits.computePassesFaster());
    GpuLimits unmeasured;
    unmeasured.computeWriteGBps = 100;
    EXPECT_FALSE(unmeasured.computePassesFaster());
    EXPECT_TRUE(GpuLimits::softwareRenderer("llvmpipe (LLVM 15.0.6, 256 bits)"));
    EXPECT_FALSE(GpuLimits::softwareRenderer("NVIDIA H100 80GB HBM3/PCIe/SSE2"));
}

// Left unset, compute passes are on where this GPU's limits say they are faster; on a software
// rasteriser (OSMesa's llvmpipe) they stay off and nothing is measured. Set, the parameter decides,
// and $FXPORT_COMPUTE_PASSES=1/0 over both.
TEST(GpuLimits, UnsetComputePassesFollowTheGpusLimits) {
    const char* env = std::getenv("FXPORT_COMPUTE_PASSES");
    const std::string forced = env && (std::string(env) == "1" || std::string(env) == "0") ? env : "";
    const char* oldCache = std::getenv("FXPORT_CACHE_DIR");
    const std::string keptCache = oldCache ? oldCache : "";
    const std::filesystem::path cache = std::filesystem::temp_directory_path() / "fxport-compute-default-test";
    std::filesystem::remove_all(cache);
    ::setenv("FXPORT_CACHE_DIR", cache.string().c_str(), 1);
    bool software = false;
    for (int set : {-1, 0, 1}) {
        PresentationParameters p;
        p.BackBufferWidth = 8;
        p.BackBufferHeight = 4;
        if (set >= 0) p.Optimizations.ComputePasses = set == 1;
        GraphicsDevice device(p);
        software = GpuLimits::softwareRenderer(device.rendererName());
        // A build without compute passes (FXPORT_PASS_COMPUTE=OFF) has none, whatever is asked.
        const bool expected = FXPORT_COMPUTE_PASSES_BUILT &&
                              (!forced.empty() ? forced == "1"
                               : set >= 0      ? set == 1
                                               : !software && GpuLimits::ForDevice(device).computePassesFaster());
        Effect effect(device, runtimeFixture("Conventions.fx"));
        effect.CurrentTechnique = effect.Techniques["SolidColor"];
        device.DepthStencilState = DepthStencilState::None;
        effect.Parameters["Color"].SetValue(Vector4(1, 0, 0, 1));
        effect.CurrentTechnique->Passes[0].Apply();
        drawQuad(device);
        EXPECT_EQ(device.computePassStatistics().issued, expected ? 1 : 0) << "ComputePasses " << set;
    }
    if (software && forced.empty()) {
        // The effect cache shares the folder; the probe writes gpu-limits-<hash>.txt.
        std::error_code ec;  // no folder: nothing was written at all
        for (const auto& entry : std::filesystem::directory_iterator(cache, ec)) {
            EXPECT_NE(entry.path().filename().string().rfind("gpu-limits-", 0), 0u) << "the probe ran: " << entry.path();
        }
    }
    if (oldCache) ::setenv("FXPORT_CACHE_DIR", keptCache.c_str(), 1);
    else ::unsetenv("FXPORT_CACHE_DIR");
    std::filesystem::remove_all(cache);
}

TEST(GpuLimits, ForDeviceMeasuresOnceThenReadsTheCache) {
    Device d;
    const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / "fxport-gpu-limits-test";
    std::filesystem::remove_all(dir);
    GpuLimits first = GpuLimits::ForDevice(*d.device, dir.string());
    ASSERT_EQ(first.fill.size(), 6u);
    std::filesystem::path file;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) file = entry.path();
    ASSERT_FALSE(file.empty());
    // A cache entry with other numbers for this renderer is what the next call returns.
    GpuLimits edited = first;
    edited.clearGBps = 12345;
    std::ofstream(file) << edited.toText();
    EXPECT_DOUBLE_EQ(GpuLimits::ForDevice(*d.device, dir.string()).clearGBps, 12345);
    // One for another renderer is measured again.
    edited.renderer = "another GPU";
    std::ofstream(file) << edited.toText();
    EXPECT_NE(GpuLimits::ForDevice(*d.device, dir.string()).clearGBps, 12345);
    std::filesystem::remove_all(dir);
}

// The fragments of each outermost section: the whole 8x4 target, then a 3x2 scissor; a nested
// section is not counted (one GL_SAMPLES_PASSED query at a time).
TEST(GpuTimer, CountsTheFragmentsEachOutermostSectionWrote) {
    Device d;
    RenderTarget2D target(*d.device, 8, 4, false, SurfaceFormat::Vector4, DepthFormat::None);
    GpuTimer timer(*d.device);
    timer.CountFragments(true);
    for (int frame = 0; frame < 2; ++frame) {
        d.device->SetRenderTarget(target);
        timer.Begin("whole");
        d.draw(Vector4(1, 0, 0, 1));
        timer.End();
        timer.Begin("scissored");
        RasterizerState scissored = RasterizerState::CullNone;
        scissored.ScissorTestEnable = true;
        d.device->RasterizerState = scissored;
        d.device->ScissorRectangle = Rectangle(2, 1, 3, 2);
        d.draw(Vector4(0, 1, 0, 1));
        d.device->RasterizerState = RasterizerState::CullNone;
        timer.Begin("nested");
        d.draw(Vector4(0, 0, 1, 1));
        timer.End();
        timer.End();
        timer.EndFrame();
    }
    timer.Finish();
    double whole = -1, scissored = -1;
    std::size_t nestedCounts = 99;
    for (const GpuTimer::Section& s : timer.Sections()) {
        if (s.name == "whole") whole = s.medianFragments();
        if (s.name == "scissored") {
            scissored = s.medianFragments();
            EXPECT_EQ(s.fragments.size(), 2u);
        }
        if (s.name == "nested") nestedCounts = s.fragments.size();
    }
    EXPECT_EQ(whole, 32);
    EXPECT_EQ(scissored, 6 + 32);  // the scissored draw and the nested whole-target one
    EXPECT_EQ(nestedCounts, 0u);
    d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
}

// Runs of draws whose pixel shaders fetch alike: SolidColor (0 fetches) over the whole 8x4 target,
// then Sample (1 tex2D) scissored to 3x2 and over the whole target: one run of 6 + 32 fragments.
TEST(FragmentTally, CountsFragmentsPerRunOfDrawsWithTheSameFetches) {
    Device d;
    RenderTarget2D target(*d.device, 8, 4, false, SurfaceFormat::Vector4, DepthFormat::None);
    Texture2D texture(*d.device, 2, 2);
    d.effect->Parameters["Tex"].SetValue(&texture);
    d.device->SetRenderTarget(target);
    d.device->tallyFragments(true);
    const std::size_t from = d.device->fragmentTallyMark();
    d.draw(Vector4(1, 0, 0, 1));
    d.effect->CurrentTechnique = d.effect->Techniques["Sample"];
    RasterizerState scissored = RasterizerState::CullNone;
    scissored.ScissorTestEnable = true;
    d.device->RasterizerState = scissored;
    d.device->ScissorRectangle = Rectangle(2, 1, 3, 2);
    d.effect->CurrentTechnique->Passes[0].Apply();
    drawQuad(*d.device);
    d.device->RasterizerState = RasterizerState::CullNone;
    d.effect->CurrentTechnique->Passes[0].Apply();
    drawQuad(*d.device);
    const std::size_t to = d.device->fragmentTallyMark();
    const std::vector<GraphicsDevice::FragmentTally> runs = d.device->fragmentTallies(from, to);
    ASSERT_EQ(runs.size(), 2u);
    EXPECT_EQ(runs[0].fragments, 32);
    EXPECT_EQ(runs[0].fetchesLeast, 0);
    EXPECT_EQ(runs[1].fragments, 6 + 32);
    EXPECT_EQ(runs[1].fetchesLeast, 1);
    EXPECT_EQ(runs[1].fetchesMost, 1);
    EXPECT_FALSE(runs[1].fetchesUnbounded);
    d.device->tallyFragments(false);
    EXPECT_TRUE(d.device->fragmentTallies(from, to).empty());
    d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
}

// GL counts one GL_SAMPLES_PASSED query at a time: with the tally on, a GpuTimer asked to count
// fragments leaves them to the tally (no GL error, no fragments in its sections).
TEST(FragmentTally, GpuTimerLeavesFragmentsToTheTally) {
    Device d;
    RenderTarget2D target(*d.device, 8, 4, false, SurfaceFormat::Vector4, DepthFormat::None);
    d.device->SetRenderTarget(target);
    d.device->tallyFragments(true);
    GpuTimer timer(*d.device);
    timer.CountFragments(true);
    const std::size_t from = d.device->fragmentTallyMark();
    timer.Begin("pass");
    d.draw(Vector4(1, 0, 0, 1));
    timer.End();
    timer.EndFrame();
    timer.Finish();
    const std::size_t to = d.device->fragmentTallyMark();
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));
    for (const GpuTimer::Section& section : timer.Sections()) EXPECT_TRUE(section.fragments.empty()) << section.name;
    const std::vector<GraphicsDevice::FragmentTally> runs = d.device->fragmentTallies(from, to);
    ASSERT_EQ(runs.size(), 1u);
    EXPECT_EQ(runs[0].fragments, 32);
    d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
}

// Only what draws wrote: a target bound at the mark but never drawn into is not listed; a depth
// buffer counts once a draw tested it (and lazy storage made it); the area is the draw's.
TEST(FragmentTally, TargetsWrittenAreThoseDrawnNotThoseOnlyBound) {
    Device d;
    RenderTarget2D withDepth(*d.device, 8, 4, false, SurfaceFormat::Color, DepthFormat::Depth24Stencil8, 0,
                             RenderTargetUsage::PreserveContents);
    RenderTarget2D plain(*d.device, 8, 4, false, SurfaceFormat::Vector4, DepthFormat::None, 0,
                         RenderTargetUsage::PreserveContents);
    d.device->SetRenderTarget(withDepth);
    d.device->markBoundTargets();
    d.device->SetRenderTarget(plain);
    d.draw(Vector4(1, 0, 0, 1));
    std::vector<GraphicsDevice::WrittenTarget> written = d.device->targetsWrittenSinceMark();
    ASSERT_EQ(written.size(), 1u);
    EXPECT_EQ(written[0].binding.RenderTarget, &plain);
    EXPECT_TRUE(written[0].color);
    EXPECT_FALSE(written[0].depthStencil);
    EXPECT_EQ(written[0].drawnPixels, 32);

    d.device->SetRenderTarget(withDepth);
    d.draw(Vector4(0, 1, 0, 1));  // DepthStencilState::None: its depth buffer is not made
    written = d.device->targetsWrittenSinceMark();
    ASSERT_EQ(written.size(), 2u);
    EXPECT_EQ(written[1].binding.RenderTarget, &withDepth);
    EXPECT_FALSE(written[1].depthStencil);
    d.device->DepthStencilState = DepthStencilState::Default;
    d.draw(Vector4(0, 0, 1, 1));
    written = d.device->targetsWrittenSinceMark();
    ASSERT_EQ(written.size(), 2u);
    EXPECT_TRUE(written[1].depthStencil);

    // The area: a draw scissored to 3x2 covers 6 pixels of the target.
    d.device->SetRenderTarget(plain);
    d.device->markBoundTargets();
    RasterizerState scissored = RasterizerState::CullNone;
    scissored.ScissorTestEnable = true;
    d.device->RasterizerState = scissored;
    d.device->ScissorRectangle = Rectangle(2, 1, 3, 2);
    d.draw(Vector4(1, 0, 1, 1));
    d.device->RasterizerState = RasterizerState::CullNone;
    written = d.device->targetsWrittenSinceMark();
    ASSERT_EQ(written.size(), 1u);
    EXPECT_EQ(written[0].drawnPixels, 6);

    d.device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
}

}  // namespace
}  // namespace fxport
