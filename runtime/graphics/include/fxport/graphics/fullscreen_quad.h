// FullscreenQuad, as the XNA 4 deferred-rendering tutorial defines it (seed 000, "FullscreenQuad"):
// four VertexPositionTexture vertices covering NDC [-1,1]^2 with UV (0,0) at the top-left, two
// clockwise triangles, drawn with DrawIndexedPrimitives.
#pragma once

#include "fxport/graphics/vertex_buffer.h"

namespace fxport {

class GraphicsDevice;

class FullscreenQuad {
public:
    explicit FullscreenQuad(GraphicsDevice& GraphicsDevice);

    // Sets the buffers and draws.
    void Draw(GraphicsDevice& GraphicsDevice);
    // Sets the buffers only (for several JustDraw calls in a row).
    void ReadyBuffers(GraphicsDevice& GraphicsDevice);
    // Draws with whatever buffers are set.
    void JustDraw(GraphicsDevice& GraphicsDevice);

private:
    VertexBuffer vb;
    IndexBuffer ib;
};

}  // namespace fxport
