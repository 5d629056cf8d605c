// XNA's hardware instancing (SetVertexBuffers with an InstanceFrequency, DrawInstancedPrimitives)
// and several vertex streams in one draw: each vertex-shader input takes the element of its
// semantic from whichever buffer holds it. The expected pixels are worked out here from the
// quads' corners (pixel centres against the instances' rectangles).
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "runtime_test_support.h"

namespace fxport::test {
namespace {

// Position from stream 0; a per-instance offset (TEXCOORD1) and colour (COLOR1) from stream 1.
const char* kInstanced = R"(
struct VSIn { float4 Position : POSITION0; float4 Offset : TEXCOORD1; float4 Color : COLOR1; };
struct VSOut { float4 Position : POSITION0; float4 Color : TEXCOORD0; };
VSOut VS(VSIn v) { VSOut o; o.Position = float4(v.Position.xy + v.Offset.xy, 0, 1); o.Color = v.Color; return o; }
float4 PS(VSOut i) : COLOR0 { return i.Color; }
technique T { pass P { VertexShader = compile vs_3_0 VS(); PixelShader = compile ps_3_0 PS(); } }
)";

struct InstanceData {
    Vector4 offset;
    Vector4 color;
};
const VertexDeclaration kInstanceDeclaration(32, {VertexElement(0, VertexElementFormat::Vector4, VertexElementUsage::TextureCoordinate, 1),
                                                  VertexElement(16, VertexElementFormat::Vector4, VertexElementUsage::Color, 1)});
const VertexDeclaration kPositionDeclaration(12, {VertexElement(0, VertexElementFormat::Vector3, VertexElementUsage::Position, 0)});

// The lower-left quadrant of clip space, as two triangles of an indexed quad.
const std::vector<Vector3> kQuad = {Vector3(-1, -1, 0), Vector3(0, -1, 0), Vector3(-1, 0, 0), Vector3(0, 0, 0)};
const std::vector<std::uint16_t> kQuadIndices = {0, 1, 2, 2, 1, 3};

std::unique_ptr<Effect> instancedEffect(GraphicsDevice& device) {
    EffectOptions options;
    options.useCache = false;
    return std::make_unique<Effect>(device, EffectSource{kInstanced, "Instanced.fx"}, options);
}

// 4x4 target cleared to black, drawn by `draw`; its pixels (rows from the top, RGBA floats).
template <class Draw>
std::vector<float> drawInto4x4(GraphicsDevice& device, Draw&& draw) {
    RenderTarget2D target(device, 4, 4, false, SurfaceFormat::Vector4);
    device.SetRenderTarget(target);
    device.Clear(Color::Black);
    device.RasterizerState = RasterizerState::CullNone;
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::None;
    draw();
    std::vector<float> px = readFloats(target);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    return px;
}

// The colour of the instance whose quad (offset + the lower-left quadrant) holds pixel (x, y)'s
// centre, the clear colour (opaque black) when none does.
std::array<float, 4> expectedAt(const std::vector<InstanceData>& instances, int x, int y) {
    const float cx = (float(x) + 0.5f) / 4 * 2 - 1, cy = 1 - (float(y) + 0.5f) / 4 * 2;
    std::array<float, 4> out{0, 0, 0, 1};
    for (const InstanceData& i : instances)
        if (cx > -1 + i.offset.X && cx < i.offset.X && cy > -1 + i.offset.Y && cy < i.offset.Y)
            out = {i.color.X, i.color.Y, i.color.Z, i.color.W};
    return out;
}

void expectPixels(const std::vector<float>& px, const std::vector<InstanceData>& instances) {
    ASSERT_EQ(px.size(), 64u);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) {
            const std::array<float, 4> want = expectedAt(instances, x, y);
            for (int c = 0; c < 4; ++c) EXPECT_NEAR(px[std::size_t((y * 4 + x) * 4 + c)], want[std::size_t(c)], 1e-4) << "pixel " << x << "," << y;
        }
}

// Three instances of the indexed quad, the per-instance rows `rows` bound from row `firstRow` on
// and advancing every `frequency` instances; the 4x4 target's pixels.
std::vector<float> drawThreeInstances(GraphicsDevice& device, const std::vector<InstanceData>& rows, int firstRow, int frequency) {
    auto effect = instancedEffect(device);
    VertexBuffer quad(device, kPositionDeclaration, 4);
    quad.SetData(kQuad);
    IndexBuffer indices(device, IndexElementSize::SixteenBits, 6);
    indices.SetData(kQuadIndices);
    VertexBuffer perInstance(device, kInstanceDeclaration, int(rows.size()));
    perInstance.SetData(rows);
    std::vector<float> px = drawInto4x4(device, [&] {
        device.SetVertexBuffers(VertexBufferBinding(quad), VertexBufferBinding(perInstance, firstRow, frequency));
        device.Indices = &indices;
        effect->CurrentTechnique->Passes[0].Apply();
        device.DrawInstancedPrimitives(PrimitiveType::TriangleList, 0, 0, 4, 0, 2, 3);
    });
    const std::vector<VertexBufferBinding> bound = device.GetVertexBuffers();
    EXPECT_EQ(bound.size(), 2u);
    EXPECT_TRUE(bound.size() == 2 && bound[1].InstanceFrequency == frequency);
    device.Indices = nullptr;
    return px;
}

TEST(HardwareInstancing, EachInstanceTakesItsOwnRowOfTheInstanceBuffer) {
    // Three of the four quadrants: lower left, lower right, upper right.
    const std::vector<InstanceData> instances = {{Vector4(0, 0, 0, 0), Vector4(1, 0, 0, 1)},
                                                 {Vector4(1, 0, 0, 0), Vector4(0, 1, 0, 1)},
                                                 {Vector4(1, 1, 0, 0), Vector4(0, 0, 1, 1)}};
    expectPixels(drawThreeInstances(testDevice(), instances, 0, 1), instances);
}

// InstanceFrequency 2: instances 0 and 1 read row 0, instance 2 row 1 (a VertexOffset of 1 skips
// the buffer's first row); instance 1 draws over instance 0 in the same place.
TEST(HardwareInstancing, FrequencyAndVertexOffsetPickTheRows) {
    const std::vector<InstanceData> rows = {{Vector4(1, 1, 0, 0), Vector4(1, 1, 1, 1)},
                                            {Vector4(0, 1, 0, 0), Vector4(1, 0, 1, 1)},
                                            {Vector4(1, 0, 0, 0), Vector4(0, 1, 1, 1)}};
    expectPixels(drawThreeInstances(testDevice(), rows, 1, 2), {rows[1], rows[2]});
}

// Two streams without instancing: positions from one buffer, offsets and colours from another,
// vertex for vertex (DrawPrimitives and DrawIndexedPrimitives).
TEST(HardwareInstancing, TwoStreamsFeedOneVertexWithoutInstancing) {
    GraphicsDevice& device = testDevice();
    auto effect = instancedEffect(device);
    VertexBuffer positions(device, kPositionDeclaration, 6);
    positions.SetData(std::vector<Vector3>{kQuad[0], kQuad[1], kQuad[2], kQuad[2], kQuad[1], kQuad[3]});
    const InstanceData same{Vector4(1, 1, 0, 0), Vector4(0.5f, 0.25f, 1, 1)};
    VertexBuffer attributes(device, kInstanceDeclaration, 6);
    attributes.SetData(std::vector<InstanceData>(6, same));
    const std::vector<float> px = drawInto4x4(device, [&] {
        device.SetVertexBuffers(VertexBufferBinding(positions), VertexBufferBinding(attributes));
        effect->CurrentTechnique->Passes[0].Apply();
        device.DrawPrimitives(PrimitiveType::TriangleList, 0, 2);
    });
    expectPixels(px, {same});
}

TEST(HardwareInstancing, BadBindingsAndCountsAreNamed) {
    GraphicsDevice& device = testDevice();
    VertexBuffer quad(device, kPositionDeclaration, 4);
    EXPECT_THROW(device.SetVertexBuffers(VertexBufferBinding(quad, 4)), ArgumentError);
    EXPECT_THROW(device.SetVertexBuffers(VertexBufferBinding(quad, 0, -1)), ArgumentError);
    EXPECT_THROW(device.SetVertexBuffers(VertexBufferBinding(static_cast<VertexBuffer*>(nullptr))), ArgumentError);
    device.SetVertexBuffers(VertexBufferBinding(quad));
    device.Indices = nullptr;
    EXPECT_THROW(device.DrawInstancedPrimitives(PrimitiveType::TriangleList, 0, 0, 4, 0, 2, 3), InvalidOperation);
    IndexBuffer indices(device, IndexElementSize::SixteenBits, 6);
    device.Indices = &indices;
    EXPECT_THROW(device.DrawInstancedPrimitives(PrimitiveType::TriangleList, 0, 0, 4, 0, 2, 0), ArgumentError);
    EXPECT_THROW(device.DrawInstancedPrimitives(PrimitiveType::TriangleList, 0, 0, 4, 0, 3, 1), ArgumentError);
    device.Indices = nullptr;
    device.SetVertexBuffer(nullptr);
    EXPECT_TRUE(device.GetVertexBuffers().empty());
}

}  // namespace
}  // namespace fxport::test
