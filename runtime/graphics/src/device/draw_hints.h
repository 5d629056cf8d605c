// INTERNAL, GL-free: what a helper that draws through the public API (SpriteBatch) may tell the
// device about its next draws, beyond the API. A hint never changes what is drawn; it lets the
// device's optimisations prove a shortcut exact (a clear the draw overwrites, copies of texels that
// one reduction can do). The helper needs nothing else of the device's internals.
#pragma once

#include <vector>

#include "fxport/graphics/graphics_device.h"
#include "fxport/graphics/texture.h"

namespace fxport {

// One sprite drawn texel for texel: target pixels [x0, x1) x [y0, y1) take the texture's texels
// from (sourceX, sourceY) on.
struct TexelCopy {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    int sourceX = 0, sourceY = 0;
};

namespace hints {

// The vertex shader the last applied pass bound, as an identity to hand back below.
const void* boundVertexShader(GraphicsDevice& device);
// Whether tryTexelCopies may take copies at all (compute passes are on).
bool texelCopiesAvailable(GraphicsDevice& device);
// Runs `copies` of `texture` (bound to Textures[0]) under the device's blend as one reduction;
// false when it cannot prove that exact (then draw them).
bool tryTexelCopies(GraphicsDevice& device, const Texture2D& texture, const std::vector<TexelCopy>& copies);
// The next draw, through `vertexShader` (boundVertexShader's), covers every pixel of the viewport:
// a pending colour clear it would overwrite may be dropped (the device checks the rest).
void nextDrawCoversViewport(GraphicsDevice& device, const void* vertexShader);

}  // namespace hints
}  // namespace fxport
