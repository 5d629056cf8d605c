// Texture2DArray (fxport; D3D10+'s Texture2DArray, GL's 2D array texture): `layers` 2D images of
// one size, format and mip chain, sampled by HLSL's Texture2DArray with (u, v, layer). Texel data
// is one level of one layer at a time, rows top first. A view sees a range of another array's
// levels and layers and shares its texels (D3D11's shader-resource view of a sub-range), or sees
// them as cubes (GL's cube map array: HLSL's TextureCubeArray).
#pragma once

#include <cstddef>
#include <cstdint>

#include "fxport/graphics/texture.h"

namespace fxport {

class Texture2DArray : public Texture {
public:
    // `levels` from 1 to the full chain of max(width, height).
    Texture2DArray(fxport::GraphicsDevice& device, int width, int height, int layers, int levels = 1,
                   SurfaceFormat format = SurfaceFormat::Color);
    // A view of `source`: levels [firstLevel, firstLevel + levels), layers [firstLayer, firstLayer +
    // layers). `source` must outlive it. ArgumentError for a range outside the source.
    Texture2DArray(Texture2DArray& source, int firstLevel, int levels, int firstLayer, int layers);
    // A view of `source`'s layers read as cubes (HLSL's TextureCubeArray; Kind::TextureCubeArray):
    // `cubes` cubes of 6 layers each from `firstLayer`, square levels. ArgumentError otherwise.
    struct Cubes {
        int firstLayer, cubes;
    };
    Texture2DArray(Texture2DArray& source, int firstLevel, int levels, Cubes cubes);
    ~Texture2DArray() override;

    int Width() const { return width_; }    // level 0's (of the view, for a view)
    int Height() const { return height_; }
    int Layers() const { return layers_; }

    // One layer of one level: `rect` (null: the whole level) of `layer`; `bytes` must be the
    // rectangle's texels of Format().
    void setData(int level, int layer, const Rectangle* rect, const void* data, std::size_t bytes);
    void getData(int level, int layer, void* data, std::size_t bytes) const;
    // The bytes of one layer of `level`.
    std::size_t layerBytes(int level) const;
    int levelWidth(int level) const { return Texture::levelWidth(width_, level); }
    int levelHeight(int level) const { return Texture::levelWidth(height_, level); }
    // fxport internals: a new backend texture over `layers` layers from `layer` of one level, 2D
    // for one layer, an array for more (Texture2D's and RenderTarget2D's constructors over layers
    // take it); ArgumentError naming `who` outside the array.
    std::uint32_t layerView(const char* who, int layer, int level, int layers = 1);

private:
    void checkSubresource(const char* call, int level, int layer) const;
    int width_;
    int height_;
    int layers_;
};

}  // namespace fxport
