// INTERNAL, GL-free: a render target over level 0 of another texture's texels, read and written in
// another format of the same bytes per texel (D3D11's render-target view of a typeless texture in
// a member of its family other than the one it is stored in: R8G8B8A8_UINT of an
// R8G8B8A8_TYPELESS texture kept as R8G8B8A8_UNORM), or over layers of one level of an array
// texture (several: layered, as RenderTarget2D's constructor over layers). Draws into it write
// `source`'s texels; it has no depth buffer, and `source` must outlive it.
#pragma once

#include "fxport/graphics/render_target.h"
#include "fxport/graphics/texture_2d_array.h"

namespace fxport::core {

class TargetView final : public RenderTarget2D {
public:
    // Throws InvalidOperation when the graphics API cannot view `source` as `format`.
    TargetView(Texture2D& source, SurfaceFormat format);
    TargetView(Texture2DArray& source, int layer, int level, int layers, SurfaceFormat format);
};

}  // namespace fxport::core
