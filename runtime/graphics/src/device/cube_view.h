// INTERNAL, GL-free: one cube of a cube array (six layers of a Texture2DArray from `firstLayer`)
// seen as a TextureCube sharing its texels -- D3D11's TEXTURECUBE shader-resource view of a cube
// array, which HLSL's TextureCube samples --, or a whole cube; either read as `format`, a format of
// the same bytes per texel (a typeless texture's view in another member of its family). `source`
// must outlive it.
#pragma once

#include "fxport/graphics/texture.h"
#include "fxport/graphics/texture_2d_array.h"

namespace fxport::core {

class CubeView final : public TextureCube {
public:
    // Levels [firstLevel, firstLevel + levels) of layers [firstLayer, firstLayer + 6). ArgumentError
    // outside `source` or for non-square levels; InvalidOperation when the API cannot make the view.
    CubeView(Texture2DArray& source, int firstLevel, int levels, int firstLayer, SurfaceFormat format);
    CubeView(TextureCube& source, SurfaceFormat format);  // every level
};

}  // namespace fxport::core
