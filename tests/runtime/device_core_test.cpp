// The device core's semantics with no GL context: the fixed-function state shadow over a recording
// backend (runtime/graphics/src/device/state_shadow.h, backend.h) and the matching of vertex-shader
// inputs to declaration elements (device/vertex_input.h). Each test fails if the core sends state
// it need not, withholds state the backend lacks, or lets a missing vertex input pass.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "device/state_shadow.h"
#include "device/vertex_input.h"
#include "fxport/graphics/errors.h"
#include "recording_backend.h"

namespace fxport {
namespace {

using Calls = std::vector<std::string>;

// The state a first draw sends (every one whole: the shadow starts as a guess), then settles.
void firstDraw(StateShadow& shadow) {
    shadow.setBlend(BlendState::Opaque);
    shadow.setDepthStencil(DepthStencilState::Default);
    shadow.setRasterizer(RasterizerState::CullCounterClockwise);
    shadow.setViewport(Viewport(0, 0, 64, 32));
    shadow.setScissor(Rectangle(0, 0, 64, 32));
    shadow.setSrgbWrite(false);
    shadow.settle();
}

TEST(StateShadow, FirstDrawSendsEveryStateWhole) {
    test::RecordingBackend backend;
    StateShadow shadow(backend);
    EXPECT_TRUE(shadow.unknown());
    firstDraw(shadow);
    EXPECT_EQ(backend.take(), (Calls{"setBlend whole", "setDepthStencil whole", "setRasterizer whole", "setViewport 64x32",
                                     "setScissor 64x32", "setSrgbWrite off"}));
    EXPECT_FALSE(shadow.unknown());
}

TEST(StateShadow, AStateEqualToTheBackendsIsNotSentAgain) {
    test::RecordingBackend backend;
    StateShadow shadow(backend);
    firstDraw(shadow);
    backend.take();
    firstDraw(shadow);  // the same states again: nothing reaches the backend
    EXPECT_EQ(backend.take(), Calls{});
    // A copy equal by value is the same state (the shadow compares fields, not objects).
    BlendState opaque = BlendState::Opaque;
    shadow.setBlend(opaque);
    EXPECT_EQ(backend.take(), Calls{});
}

TEST(StateShadow, AChangedStateIsSentWithWhatTheBackendHad) {
    test::RecordingBackend backend;
    StateShadow shadow(backend);
    firstDraw(shadow);
    backend.take();
    shadow.setBlend(BlendState::Additive);
    shadow.setDepthStencil(DepthStencilState::DepthRead);
    EXPECT_EQ(backend.take(), (Calls{"setBlend changed", "setDepthStencil changed"}));
    EXPECT_EQ(backend.blend, BlendState::Additive);
    EXPECT_EQ(backend.hadBlend, BlendState::Opaque);
    EXPECT_EQ(shadow.blend(), BlendState::Additive);
    // One field differs: still sent (a field-by-field backend sets only that one).
    BlendState factor = BlendState::Additive;
    factor.BlendFactor = Color(1, 2, 3, 4);
    shadow.setBlend(factor);
    EXPECT_EQ(backend.take(), Calls{"setBlend changed"});
    EXPECT_EQ(backend.blend.BlendFactor, Color(1, 2, 3, 4));
}

TEST(StateShadow, PointSizeIsSentWhenItOrItsSourceChanges) {
    test::RecordingBackend backend;
    StateShadow shadow(backend);
    firstDraw(shadow);
    backend.take();
    shadow.setPointSize(1, false);  // what the settled shadow holds: not sent
    shadow.setPointSize(1, false);
    shadow.setPointSize(12.5f, false);
    shadow.setPointSize(12.5f, true);  // the vertex shader's PSIZE from now on
    EXPECT_EQ(backend.take(), (Calls{"setPointSize 12.500000", "setPointSize 12.500000 shader"}));
}

TEST(StateShadow, InvalidateSendsEverythingWholeAtTheNextDraw) {
    test::RecordingBackend backend;
    StateShadow shadow(backend);
    firstDraw(shadow);
    backend.take();
    shadow.invalidate();  // a measurement or a front end's clear changed GL behind the shadow
    EXPECT_TRUE(shadow.unknown());
    firstDraw(shadow);  // equal states, but the backend's are unknown
    EXPECT_EQ(backend.take(), (Calls{"setBlend whole", "setDepthStencil whole", "setRasterizer whole", "setViewport 64x32",
                                     "setScissor 64x32", "setSrgbWrite off"}));
}

TEST(StateShadow, ReapplyRestoresWhatAClearChangesAndNothingElse) {
    test::RecordingBackend backend;
    StateShadow shadow(backend);
    firstDraw(shadow);
    shadow.setBlend(BlendState::NonPremultiplied);
    backend.take();
    shadow.reapply();  // a clear set the write masks and the scissor test for itself
    EXPECT_EQ(backend.take(),
              (Calls{"setBlend whole", "setDepthStencil whole", "setRasterizer whole", "setScissor 64x32"}));
    EXPECT_EQ(backend.blend, BlendState::NonPremultiplied);
    EXPECT_EQ(backend.depthStencil, DepthStencilState::Default);
    EXPECT_FALSE(shadow.unknown());  // the viewport and bindings were not touched by the clear
}

TEST(StateShadow, ViewportSaysWhetherItWasSent) {
    test::RecordingBackend backend;
    StateShadow shadow(backend);
    EXPECT_TRUE(shadow.setViewport(Viewport(0, 0, 8, 8)));
    shadow.settle();
    EXPECT_FALSE(shadow.setViewport(Viewport(0, 0, 8, 8)));
    Viewport depthRange(0, 0, 8, 8);
    depthRange.MaxDepth = 0.5f;
    EXPECT_TRUE(shadow.setViewport(depthRange));  // the depth range is part of the viewport
    EXPECT_EQ(backend.take(), (Calls{"setViewport 8x8", "setViewport 8x8"}));
    EXPECT_EQ(backend.viewport.MaxDepth, 0.5f);
}

// The D3D9 pixel-centre shift (an SM1-3 vertex shader's) is part of the viewport: a draw with another
// kind of vertex shader over the same viewport sends it again, without the shift.
TEST(StateShadow, ViewportShiftIsPartOfTheViewport) {
    test::RecordingBackend backend;
    StateShadow shadow(backend);
    const ViewportShift d3d9{0.5f, 0.5f - 1.0f / 256.0f};
    EXPECT_TRUE(shadow.setViewport(Viewport(0, 0, 8, 8), d3d9));
    shadow.settle();
    EXPECT_FALSE(shadow.setViewport(Viewport(0, 0, 8, 8), d3d9));
    EXPECT_TRUE(shadow.setViewport(Viewport(0, 0, 8, 8)));
    EXPECT_EQ(backend.take(), (Calls{"setViewport 8x8 shifted", "setViewport 8x8"}));
    EXPECT_EQ(backend.viewportShift, ViewportShift{});
}

TEST(StateShadow, SrgbWriteIsSentOnChange) {
    test::RecordingBackend backend;
    StateShadow shadow(backend);
    firstDraw(shadow);
    backend.take();
    shadow.setSrgbWrite(true);
    shadow.setSrgbWrite(true);
    shadow.setSrgbWrite(false);
    EXPECT_EQ(backend.take(), (Calls{"setSrgbWrite on", "setSrgbWrite off"}));
}

xlate::VertexInput input(const std::string& semantic, int location) {
    xlate::VertexInput in;
    in.semantic = semantic;
    in.location = location;
    return in;
}

VertexDeclaration positionTexture() {
    return VertexDeclaration({VertexElement(0, VertexElementFormat::Vector3, VertexElementUsage::Position, 0),
                              VertexElement(12, VertexElementFormat::Vector2, VertexElementUsage::TextureCoordinate, 0),
                              VertexElement(20, VertexElementFormat::Vector2, VertexElementUsage::TextureCoordinate, 1)});
}

TEST(VertexInput, AMissingInputIsAnInvalidOperationNamingTheShaderAndTheSemantic) {
    const VertexDeclaration declaration = positionTexture();
    try {
        vertexElementsFor(declaration, {input("POSITION0", 0), input("NORMAL0", 1)}, "'VertexShaderFunction'");
        FAIL() << "a vertex shader reading NORMAL0 drew from a declaration without it";
    } catch (const InvalidOperation& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("'VertexShaderFunction'"), std::string::npos) << what;
        EXPECT_NE(what.find("NORMAL0 is missing"), std::string::npos) << what;
    }
}

TEST(VertexInput, InputsMatchByUsageAndUsageIndexInShaderOrder) {
    const VertexDeclaration declaration = positionTexture();
    const std::vector<const VertexElement*> elements =
        vertexElementsFor(declaration, {input("TEXCOORD1", 0), input("POSITION0", 1), input("TEXCOORD0", 2)}, "'VS'");
    ASSERT_EQ(elements.size(), 3u);
    EXPECT_EQ(elements[0]->Offset, 20);
    EXPECT_EQ(elements[1]->Offset, 0);
    EXPECT_EQ(elements[2]->Offset, 12);
}

TEST(VertexInput, SvPositionTakesThePositionElement) {
    const VertexDeclaration declaration = positionTexture();
    EXPECT_EQ(vertexElementFor(declaration, input("SV_POSITION0", 0), "'VS'").Offset, 0);
    // Only SV_Position is renamed to a usage: another SV_ semantic matches no element.
    EXPECT_THROW(vertexElementFor(declaration, input("SV_TARGET0", 0), "'VS'"), InvalidOperation);
}

}  // namespace
}  // namespace fxport
