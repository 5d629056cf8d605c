// Texture1D (fxport; D3D10+'s Texture1D and Texture1DArray, GL's 1D and 1D array textures):
// `layers` rows of `width` texels of one format and mip chain, sampled by HLSL's Texture1D with u
// (a plain 1D texture, one layer) or Texture1DArray with (u, layer) (an array texture). Texel data
// is one level of one layer at a time. A view sees a range of another 1D texture's levels and
// layers and shares its texels (D3D11's shader-resource view of a sub-range).
#pragma once

#include <cstddef>
#include <cstdint>

#include "fxport/graphics/texture.h"

namespace fxport {

class Texture1D : public Texture {
public:
    // `levels` from 1 to the full chain of `width`; `array` false takes one layer.
    Texture1D(fxport::GraphicsDevice& device, int width, int layers = 1, int levels = 1, SurfaceFormat format = SurfaceFormat::Color,
              bool array = false);
    // A view of `source`: levels [firstLevel, firstLevel + levels), layers [firstLayer, firstLayer +
    // layers), an array (`array`) or a plain 1D texture (one layer). `source` must outlive it.
    // ArgumentError for a range outside the source.
    Texture1D(Texture1D& source, int firstLevel, int levels, int firstLayer, int layers, bool array);
    ~Texture1D() override;

    int Width() const { return width_; }  // level 0's (of the view, for a view)
    int Layers() const { return layers_; }
    bool isArray() const { return kind_ == Kind::Texture1DArray; }

    // Texels [x, x + count) of one layer of one level; `bytes` must be `count` texels of Format().
    void setData(int level, int layer, int x, int count, const void* data, std::size_t bytes);
    void getData(int level, int layer, void* data, std::size_t bytes) const;  // the whole row
    std::size_t rowBytes(int level) const;  // one layer of `level`
    int levelWidth(int level) const { return Texture::levelWidth(width_, level); }
    // fxport internals: a new backend texture over `layers` layers from `layer` of one level, 1D for
    // one layer, a 1D array for more (RenderTarget2D's and Texture2D's constructors over rows take
    // it: D3D11's 1D render-target and depth-stencil views); ArgumentError naming `who` outside it.
    std::uint32_t rowView(const char* who, int layer, int level, int layers = 1);

private:
    void checkSubresource(const char* call, int level, int layer) const;
    int face(int layer) const { return isArray() ? layer : -1; }  // the backend's address of a layer
    int width_;
    int layers_;
};

}  // namespace fxport
