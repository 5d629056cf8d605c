// INTERNAL, GL-free: a range of an array texture's levels and layers read as another format of the
// same bytes per texel (D3D11's shader-resource view of a typeless array in a member of its
// family other than the one it is stored in). It shares the texels; `source` must outlive it.
#pragma once

#include "fxport/graphics/texture_2d_array.h"

namespace fxport::core {

class ArrayFormatView final : public Texture2DArray {
public:
    // ArgumentError outside `source`; InvalidOperation when the API cannot view it as `format`.
    ArrayFormatView(Texture2DArray& source, int firstLevel, int levels, int firstLayer, int layers, SurfaceFormat format);
    // The same read as cubes (a cube array's TEXTURECUBEARRAY view: Texture::Kind::TextureCubeArray).
    ArrayFormatView(Texture2DArray& source, int firstLevel, int levels, Cubes cubes, SurfaceFormat format);
};

}  // namespace fxport::core
