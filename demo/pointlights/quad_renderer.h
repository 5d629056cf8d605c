// QuadRenderer (the series' helper, chapter 2; not in seed 001, reconstructed): draws a quad
// between two corners in screen space [-1,1]^2 with texture coordinates (0,0) at the top left,
// using DrawUserIndexedPrimitives, as the series' QuadRenderer component does.
#pragma once

#include "pointlights/xna.h"

namespace DeferredLighting {

class QuadRenderer {
    VertexPositionTexture verts[4];
    short ib[6];

public:
    explicit QuadRenderer(GraphicsDevice& device);
    void Render(Vector2 v1, Vector2 v2);

private:
    GraphicsDevice* device;
};

}  // namespace DeferredLighting
