// Texture3D: a volume of width x height x depth texels (XNA's Texture3D), sampled by HLSL's
// tex3D / Texture3D. Texel data is a whole level at a time: slices front to back, each slice's
// rows top first, as D3D lays out a 3D subresource.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "fxport/graphics/texture.h"

namespace fxport {

class Texture3D : public Texture {
public:
    Texture3D(fxport::GraphicsDevice& device, int width, int height, int depth, bool mipMap = false,
              SurfaceFormat format = SurfaceFormat::Color);
    ~Texture3D() override;

    // A volume .dds (DDSCAPS2_VOLUME or DX10 TEXTURE3D; the formats Texture2D::FromFile reads), decoded
    // to SurfaceFormat::Color with its mip levels as stored; a partial chain is completed by averaging
    // 2x2x2 texels. Throws ArgumentError naming the file (a 2D texture or cube map included).
    static std::unique_ptr<Texture3D> FromFile(fxport::GraphicsDevice& device, const std::string& path);

    int Width() const { return width_; }
    int Height() const { return height_; }
    int Depth() const { return depth_; }

    // T is the texel type of Format(); sizeof(T) * count must equal the bytes of the whole level.
    template <class T> void SetData(const T* data, std::size_t count) { setData(0, data, sizeof(T) * count, sizeof(T)); }
    template <class T> void SetData(int level, const T* data, std::size_t count) { setData(level, data, sizeof(T) * count, sizeof(T)); }
    template <class T> void GetData(T* data, std::size_t count) const { getData(0, data, sizeof(T) * count); }

    void setData(int level, const void* data, std::size_t bytes, std::size_t elementSize = 1);
    void getData(int level, void* data, std::size_t bytes) const;
    // The bytes of one level (width x height x depth texels of Format()).
    std::size_t levelBytes(int level) const;

private:
    void checkLevel(const char* call, int level) const;
    int width_;
    int height_;
    int depth_;
};

}  // namespace fxport
