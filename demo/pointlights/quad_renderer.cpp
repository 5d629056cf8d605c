#include "pointlights/quad_renderer.h"

namespace DeferredLighting {

// Reconstructed (QuadRenderer.cs is not in seed 001): the series' LoadContent builds the four
// vertices and the index list once; Render moves the corners.
QuadRenderer::QuadRenderer(GraphicsDevice& device) : device(&device) {
    verts[0] = VertexPositionTexture(Vector3(1, -1, 0), Vector2(1, 1));
    verts[1] = VertexPositionTexture(Vector3(-1, -1, 0), Vector2(0, 1));
    verts[2] = VertexPositionTexture(Vector3(-1, 1, 0), Vector2(0, 0));
    verts[3] = VertexPositionTexture(Vector3(1, 1, 0), Vector2(1, 0));
    ib[0] = 0; ib[1] = 1; ib[2] = 2;
    ib[3] = 2; ib[4] = 3; ib[5] = 0;
}

void QuadRenderer::Render(Vector2 v1, Vector2 v2) {
    verts[0].Position.X = v2.X;
    verts[0].Position.Y = v1.Y;

    verts[1].Position.X = v1.X;
    verts[1].Position.Y = v1.Y;

    verts[2].Position.X = v1.X;
    verts[2].Position.Y = v2.Y;

    verts[3].Position.X = v2.X;
    verts[3].Position.Y = v2.Y;

    device->DrawUserIndexedPrimitives(PrimitiveType::TriangleList, verts, 0, 4, ib, 0, 2);
}

}  // namespace DeferredLighting
