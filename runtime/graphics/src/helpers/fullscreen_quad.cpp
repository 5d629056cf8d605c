#include "fxport/graphics/fullscreen_quad.h"

#include <cstdint>

#include "fxport/graphics/graphics_device.h"
#include "fxport/graphics/vertex_types.h"

namespace fxport {

namespace {

const VertexPositionTexture kVertices[4] = {
    VertexPositionTexture(Vector3(1, -1, 0), Vector2(1, 1)),
    VertexPositionTexture(Vector3(-1, -1, 0), Vector2(0, 1)),
    VertexPositionTexture(Vector3(-1, 1, 0), Vector2(0, 0)),
    VertexPositionTexture(Vector3(1, 1, 0), Vector2(1, 0)),
};
const std::uint16_t kIndices[6] = {0, 1, 2, 2, 3, 0};

}  // namespace

FullscreenQuad::FullscreenQuad(GraphicsDevice& GraphicsDevice)
    : vb(GraphicsDevice, VertexPositionTexture::VertexDeclaration, 4, BufferUsage::None),
      ib(GraphicsDevice, IndexElementSize::SixteenBits, 6, BufferUsage::None) {
    vb.Name = "FullscreenQuad";
    ib.Name = "FullscreenQuad";
    vb.SetData(kVertices, 4);
    ib.SetData(kIndices, 6);
}

void FullscreenQuad::Draw(GraphicsDevice& GraphicsDevice) {
    ReadyBuffers(GraphicsDevice);
    JustDraw(GraphicsDevice);
}

void FullscreenQuad::ReadyBuffers(GraphicsDevice& GraphicsDevice) {
    GraphicsDevice.SetVertexBuffer(vb);
    GraphicsDevice.Indices = &ib;
}

void FullscreenQuad::JustDraw(GraphicsDevice& GraphicsDevice) {
    GraphicsDevice.DrawIndexedPrimitives(PrimitiveType::TriangleList, 0, 0, 4, 0, 2);
}

}  // namespace fxport
