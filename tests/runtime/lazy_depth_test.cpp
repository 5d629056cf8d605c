// Depth/stencil buffers made at the first draw that needs them (runtime/graphics/src/depth_storage.cpp):
// a target drawn without depth gets none, a depth-tested draw gets one that holds exactly what the
// clears before it left (pending, waiting on a PreserveContents target, or partial), MRT bindings
// use the first target's buffer, and the pixels are the value the clears and depth tests must give,
// with the buffers made lazily or with their targets, clears deferred or immediate.
#include <gtest/gtest.h>

#include "runtime_test_support.h"

namespace fxport {
namespace {

using test::drawQuad;
using test::readFloats;
using test::runtimeFixture;

constexpr int kWidth = 8, kHeight = 4;
constexpr std::int64_t kD24S8Bytes = kWidth * kHeight * 4;

struct Mode {
    bool lazy;
    bool defer;
    std::string name() const { return std::string(lazy ? "lazy" : "eager") + (defer ? ", deferred clears" : ", immediate clears"); }
};
const Mode kModes[] = {{true, true}, {true, false}, {false, true}, {false, false}};

struct Device {
    explicit Device(Mode mode) {
        PresentationParameters p;
        p.BackBufferWidth = kWidth;
        p.BackBufferHeight = kHeight;
        p.Optimizations.DeferClears = mode.defer;
        p.Optimizations.LazyDepthStorage = mode.lazy;
        device = std::make_unique<GraphicsDevice>(p);
        effect = std::make_unique<Effect>(*device, runtimeFixture("Conventions.fx"));
        device->BlendState = BlendState::Opaque;
        device->RasterizerState = RasterizerState::CullNone;
    }
    // A full-target quad at depth z in one colour (SolidColor), or the MRT technique's colours.
    void draw(Vector4 color, const DepthStencilState& depth, float z, const char* technique = "SolidColor") {
        effect->CurrentTechnique = effect->Techniques[technique];
        effect->Parameters["Color"].SetValue(color);
        device->DepthStencilState = depth;
        effect->CurrentTechnique->Passes[0].Apply();
        drawQuad(*device, z);
    }
    void unbind() { device->SetRenderTarget(static_cast<RenderTarget2D*>(nullptr)); }
    std::unique_ptr<GraphicsDevice> device;
    std::unique_ptr<Effect> effect;
};

std::vector<float> texel(const std::vector<float>& texels, int index) {
    return std::vector<float>(texels.begin() + index * 4, texels.begin() + index * 4 + 4);
}

void expectEvery(RenderTarget2D& target, const std::vector<float>& expected) {
    std::vector<float> texels = readFloats(target);
    for (int i = 0; i < kWidth * kHeight; ++i) EXPECT_EQ(texel(texels, i), expected) << "texel " << i;
}

const DepthStencilState& writeNoTest() {
    static const DepthStencilState state = [] {
        DepthStencilState s = DepthStencilState::Default;
        s.DepthBufferEnable = false;  // D3D: no test, no write, whatever DepthBufferWriteEnable says
        return s;
    }();
    return state;
}

// Drawn without a depth test, a target with a DepthFormat has no buffer (but reports its format);
// the first depth-tested draw makes one, and the depth clear pending since then is honoured: a quad
// behind the cleared 0.5 is rejected, one in front drawn and its depth written.
TEST(LazyDepthStorage, BufferMadeAtTheFirstDepthTestedDraw) {
    for (Mode mode : kModes) {
        SCOPED_TRACE(mode.name());
        Device d(mode);
        const DepthStorageStatistics start = d.device->depthStorageStatistics();
        RenderTarget2D target(*d.device, kWidth, kHeight, false, SurfaceFormat::Vector4, DepthFormat::Depth24Stencil8);
        EXPECT_EQ(target.DepthStencilFormat(), DepthFormat::Depth24Stencil8);
        d.device->SetRenderTarget(target);
        d.draw(Vector4(1, 0, 0, 1), DepthStencilState::None, 0.5f);
        d.draw(Vector4(1, 0, 0, 1), writeNoTest(), 0.5f);
        EXPECT_EQ(target.depthRenderbuffer() != 0, !mode.lazy) << "made before any draw tested depth";
        EXPECT_EQ(d.device->depthStorageStatistics().requested - start.requested, 1);
        d.device->Clear(ClearOptions::DepthBuffer, Vector4(), 0.5f, 0);
        d.draw(Vector4(0, 1, 0, 1), DepthStencilState::Default, 0.75f);   // behind 0.5: rejected
        EXPECT_NE(target.depthRenderbuffer(), 0u);
        d.draw(Vector4(0, 0, 1, 1), DepthStencilState::Default, 0.25f);   // in front: drawn, writes 0.25
        d.draw(Vector4(1, 1, 1, 1), DepthStencilState::Default, 0.375f);  // behind 0.25: rejected
        d.unbind();
        expectEvery(target, {0, 0, 1, 1});
        const DepthStorageStatistics end = d.device->depthStorageStatistics();
        EXPECT_EQ(end.allocated - start.allocated, 1);
        EXPECT_EQ(end.allocatedBytes - start.allocatedBytes, kD24S8Bytes);
        // Leaving the DiscardContents target gave its depth up (XNA clears it at the next binding).
        EXPECT_EQ(end.invalidated - start.invalidated, mode.lazy ? 1 : 0);
    }
}

// The counter: a target that only ever draws colour keeps no buffer, and its bytes are counted as
// saved; disposing it releases nothing it did not make.
TEST(LazyDepthStorage, TargetNeverDrawnWithDepthTakesNoMemory) {
    for (Mode mode : kModes) {
        SCOPED_TRACE(mode.name());
        Device d(mode);
        const GpuObjectCounts liveBefore = d.device->liveGpuObjects();
        const DepthStorageStatistics start = d.device->depthStorageStatistics();
        {
            RenderTarget2D target(*d.device, kWidth, kHeight, false, SurfaceFormat::Vector4, DepthFormat::Depth24Stencil8);
            for (int frame = 0; frame < 3; ++frame) {
                d.device->SetRenderTarget(target);
                d.device->Clear(Color::Black);
                d.draw(Vector4(0.25f, 0.5f, 0.75f, 1), DepthStencilState::None, 0.5f);
                d.unbind();
            }
            expectEvery(target, {0.25f, 0.5f, 0.75f, 1});
            EXPECT_EQ(target.depthRenderbuffer() != 0, !mode.lazy);
            EXPECT_EQ(d.device->liveGpuObjects().renderbuffers - liveBefore.renderbuffers, mode.lazy ? 0 : 1);
        }
        const DepthStorageStatistics end = d.device->depthStorageStatistics();
        EXPECT_EQ(end.requested - start.requested, 1);
        EXPECT_EQ(end.allocated - start.allocated, mode.lazy ? 0 : 1);
        EXPECT_EQ(end.savedBytes() - start.savedBytes(), mode.lazy ? kD24S8Bytes : 0);
        EXPECT_EQ(d.device->liveGpuObjects().renderbuffers, liveBefore.renderbuffers);
    }
}

// PreserveContents: a depth clear made while the target had no buffer is kept with the target when
// it is left, and is the buffer's content when a later binding first tests depth.
TEST(LazyDepthStorage, PreserveContentsKeepsTheClearUntilTheBufferIsMade) {
    for (Mode mode : kModes) {
        SCOPED_TRACE(mode.name());
        Device d(mode);
        RenderTarget2D target(*d.device, kWidth, kHeight, false, SurfaceFormat::Vector4, DepthFormat::Depth24Stencil8, 0,
                              RenderTargetUsage::PreserveContents);
        d.device->SetRenderTarget(target);
        d.device->Clear(ClearOptions::Target | ClearOptions::DepthBuffer, Vector4(0, 0, 0, 1), 0.5f, 0);
        d.draw(Vector4(1, 0, 0, 1), DepthStencilState::None, 0.9f);
        d.unbind();
        EXPECT_EQ(target.depthRenderbuffer() != 0, !mode.lazy);
        d.device->SetRenderTarget(target);  // PreserveContents: no clear
        d.draw(Vector4(0, 1, 0, 1), DepthStencilState::Default, 0.75f);  // behind the kept 0.5: rejected
        d.draw(Vector4(1, 0, 1, 1), DepthStencilState::DepthRead, 0.5f);  // LessEqual 0.5: drawn, not written
        d.draw(Vector4(0, 0, 1, 1), DepthStencilState::Default, 0.625f);  // still behind 0.5: rejected
        d.unbind();
        EXPECT_NE(target.depthRenderbuffer(), 0u);
        expectEvery(target, {1, 0, 1, 1});
    }
}

// A depth test that cannot fail (LessEqual against the bind clear's 1, writes off: the tutorials'
// DepthRead light passes) needs no buffer; against a clear to 0.5 it can fail, and gets one.
TEST(LazyDepthStorage, DepthReadAgainstTheFarClearNeedsNoBuffer) {
    for (Mode mode : kModes) {
        SCOPED_TRACE(mode.name());
        Device d(mode);
        RenderTarget2D target(*d.device, kWidth, kHeight, false, SurfaceFormat::Vector4, DepthFormat::Depth24Stencil8);
        d.device->SetRenderTarget(target);
        d.device->Clear(Color::Black);
        d.draw(Vector4(0.5f, 0, 0, 1), DepthStencilState::DepthRead, 1.0f);  // on the far plane: LessEqual 1 passes
        EXPECT_EQ(target.depthRenderbuffer() != 0, !mode.lazy);
        d.unbind();
        expectEvery(target, {0.5f, 0, 0, 1});

        d.device->SetRenderTarget(target);
        d.device->Clear(ClearOptions::Target | ClearOptions::DepthBuffer, Vector4(0, 0, 0, 1), 0.5f, 0);
        d.draw(Vector4(0, 0.5f, 0, 1), DepthStencilState::DepthRead, 0.75f);  // behind 0.5: rejected
        EXPECT_NE(target.depthRenderbuffer(), 0u);
        d.unbind();
        expectEvery(target, {0, 0, 0, 1});
    }
}

// MRT: the first target's buffer serves the binding (XNA's rule); the others' are not made.
TEST(LazyDepthStorage, MultipleTargetsUseTheFirstTargetsBuffer) {
    for (Mode mode : kModes) {
        SCOPED_TRACE(mode.name());
        Device d(mode);
        RenderTarget2D first(*d.device, kWidth, kHeight, false, SurfaceFormat::Vector4, DepthFormat::Depth24Stencil8);
        RenderTarget2D second(*d.device, kWidth, kHeight, false, SurfaceFormat::Vector4, DepthFormat::Depth24Stencil8);
        d.device->SetRenderTargets({first, second});
        d.device->Clear(ClearOptions::Target | ClearOptions::DepthBuffer, Vector4(0, 0, 0, 1), 0.5f, 0);
        d.draw(Vector4(), DepthStencilState::Default, 0.75f, "MRT");  // behind 0.5: rejected in both
        d.draw(Vector4(), DepthStencilState::Default, 0.25f, "MRT");  // drawn: red and green
        EXPECT_NE(first.depthRenderbuffer(), 0u);
        EXPECT_EQ(second.depthRenderbuffer() != 0, !mode.lazy);
        d.unbind();
        expectEvery(first, {1, 0, 0, 1});
        expectEvery(second, {0, 1, 0, 1});
    }
}

// A depth clear of part of a target without a buffer makes it at once, after the whole-target clear
// before it: left half 0.25 (the partial clear), right half 1 (the bind clear). A quad at 0.5 is drawn
// only on the right.
TEST(LazyDepthStorage, PartialDepthClearMakesTheBufferAfterTheWholeClear) {
    for (Mode mode : kModes) {
        SCOPED_TRACE(mode.name());
        Device d(mode);
        RenderTarget2D target(*d.device, kWidth, kHeight, false, SurfaceFormat::Vector4, DepthFormat::Depth24Stencil8);
        d.device->SetRenderTarget(target);
        d.device->Clear(Color::Black);
        d.device->Viewport = Viewport(0, 0, kWidth / 2, kHeight);
        d.device->Clear(ClearOptions::DepthBuffer, Vector4(), 0.25f, 0);
        EXPECT_NE(target.depthRenderbuffer(), 0u);
        d.device->Viewport = Viewport(0, 0, kWidth, kHeight);
        d.draw(Vector4(0, 0, 1, 1), DepthStencilState::Default, 0.5f);
        d.unbind();
        std::vector<float> texels = readFloats(target);
        for (int y = 0; y < kHeight; ++y)
            for (int x = 0; x < kWidth; ++x)
                EXPECT_EQ(texel(texels, y * kWidth + x), (x < kWidth / 2 ? std::vector<float>{0, 0, 0, 1}
                                                                           : std::vector<float>{0, 0, 1, 1}))
                    << x << "," << y;
    }
}

// A stencil test needs the buffer too, with its pending stencil clear: a quad drawn where stencil
// equals the cleared 3 passes, one where it equals 0 does not.
TEST(LazyDepthStorage, StencilTestMakesTheBufferWithItsClear) {
    DepthStencilState equal = DepthStencilState::None;
    equal.StencilEnable = true;
    equal.StencilFunction = CompareFunction::Equal;
    for (Mode mode : kModes) {
        SCOPED_TRACE(mode.name());
        Device d(mode);
        RenderTarget2D target(*d.device, kWidth, kHeight, false, SurfaceFormat::Vector4, DepthFormat::Depth24Stencil8);
        d.device->SetRenderTarget(target);
        d.device->Clear(ClearOptions::Target | ClearOptions::Stencil, Vector4(0, 0, 0, 1), 1, 3);
        equal.ReferenceStencil = 0;
        d.draw(Vector4(1, 0, 0, 1), equal, 0.5f);  // stencil is 3: rejected
        EXPECT_NE(target.depthRenderbuffer(), 0u);
        equal.ReferenceStencil = 3;
        d.draw(Vector4(0, 1, 0, 1), equal, 0.5f);
        d.unbind();
        expectEvery(target, {0, 1, 0, 1});
    }
}

// A cube target's one buffer (shared by its faces) is made at the first depth-tested draw on a face.
TEST(LazyDepthStorage, CubeTargetBufferMadeAtTheFirstDepthTestedDraw) {
    for (Mode mode : kModes) {
        SCOPED_TRACE(mode.name());
        Device d(mode);
        RenderTargetCube cube(*d.device, kHeight, false, SurfaceFormat::Vector4, DepthFormat::Depth24Stencil8);
        d.device->SetRenderTarget(cube, CubeMapFace::PositiveX);
        d.draw(Vector4(1, 0, 0, 1), DepthStencilState::None, 0.5f);
        EXPECT_EQ(cube.depthRenderbuffer() != 0, !mode.lazy);
        d.device->SetRenderTarget(cube, CubeMapFace::NegativeY);
        d.device->Clear(ClearOptions::Target | ClearOptions::DepthBuffer, Vector4(0, 0, 0, 1), 0.5f, 0);
        d.draw(Vector4(0, 1, 0, 1), DepthStencilState::Default, 0.75f);  // behind 0.5: rejected
        d.draw(Vector4(0, 0, 1, 1), DepthStencilState::Default, 0.25f);
        EXPECT_NE(cube.depthRenderbuffer(), 0u);
        d.unbind();
        const std::vector<Vector4> positiveX = cube.GetDataAsVector4(CubeMapFace::PositiveX);
        const std::vector<Vector4> negativeY = cube.GetDataAsVector4(CubeMapFace::NegativeY);
        for (std::size_t i = 0; i < positiveX.size(); ++i) {
            EXPECT_TRUE(positiveX[i] == Vector4(1, 0, 0, 1)) << "+X texel " << i;
            EXPECT_TRUE(negativeY[i] == Vector4(0, 0, 1, 1)) << "-Y texel " << i;
        }
    }
}

// The back buffer's depth buffer is lazy too: a 2D frame leaves it unmade, a depth-tested draw
// makes it.
TEST(LazyDepthStorage, BackBufferBufferMadeWhenFirstNeeded) {
    for (Mode mode : kModes) {
        SCOPED_TRACE(mode.name());
        Device d(mode);
        EXPECT_EQ(d.device->PresentationParameters().DepthStencilFormat, DepthFormat::Depth24Stencil8);
        RenderTarget2D& backBuffer = d.device->backBufferTarget();
        EXPECT_EQ(backBuffer.DepthStencilFormat(), DepthFormat::Depth24Stencil8);
        d.device->Clear(Color::Black);
        d.draw(Vector4(1, 0, 0, 1), DepthStencilState::None, 0.5f);
        EXPECT_EQ(backBuffer.depthRenderbuffer() != 0, !mode.lazy);
        d.device->Clear(ClearOptions::DepthBuffer, Vector4(), 0.5f, 0);
        d.draw(Vector4(0, 1, 0, 1), DepthStencilState::Default, 0.75f);  // rejected
        EXPECT_NE(backBuffer.depthRenderbuffer(), 0u);
        for (const Color& c : d.device->GetBackBufferData()) EXPECT_TRUE(c == Color(255, 0, 0, 255));
    }
}

}  // namespace
}  // namespace fxport
