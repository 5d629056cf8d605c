// Textures: Texture2D (load PNG, SetData/GetData in any SurfaceFormat) and TextureCube. Render
// targets derive from these (render_target.h). Texel data is stored top row first, as D3D does.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "fxport/graphics/graphics_resource.h"
#include "fxport/graphics/surface_format.h"
#include "fxport/math.h"

namespace fxport {

// XNA's order of cube faces (also D3D's and GL's).
enum class CubeMapFace : std::uint8_t { PositiveX, NegativeX, PositiveY, NegativeY, PositiveZ, NegativeZ };

class Texture : public GraphicsResource {
public:
    enum class Kind : std::uint8_t { Texture2D, TextureCube, Texture3D, Texture2DArray, Texture1D, Texture1DArray, TextureCubeArray };

    SurfaceFormat Format() const { return format_; }
    int LevelCount() const { return levels_; }
    Kind kind() const { return kind_; }
    // The backend's object for this texture (an integer; for fxport internals and interop).
    std::uint32_t backendObject() const { return name_; }
    // True for RenderTarget2D / RenderTargetCube.
    virtual bool isRenderTarget() const { return false; }
    // fxport: samples per texel of a multisampled texture (D3D11's SampleDesc.Count > 1), 0 for
    // any other. Its texels are not read or written directly: a resolve reads them.
    int sampleCount() const { return samples_; }

protected:
    Texture(fxport::GraphicsDevice& device, const char* typeName, Kind kind, SurfaceFormat format, int levels);
    void releaseGpuObjects() override;
    // Uploads/reads raw texels of one level (face = -1 for 2D). Checks the byte count; its error
    // counts in the caller's elements of `elementSize` bytes.
    void writeTexels(int face, int level, int x, int y, int w, int h, const void* data, std::size_t bytes, std::size_t elementSize = 1);
    void readTexels(int face, int level, void* data, std::size_t bytes) const;
    int levelWidth(int base, int level) const;
    // Throws ArgumentError when a compressed format's region `r` of a levelWidth x levelHeight level
    // is off its 4x4 block grid (whole faces and levels always lie on it).
    void checkBlockGrid(const Rectangle& r, int levelWidth, int levelHeight) const;

    std::uint32_t name_ = 0;
    int samples_ = 0;
    SurfaceFormat format_;
    int levels_;
    Kind kind_;
};

class Texture2DArray;
class Texture1D;

class Texture2D : public Texture {
public:
    Texture2D(fxport::GraphicsDevice& device, int width, int height, bool mipMap = false,
              SurfaceFormat format = SurfaceFormat::Color);
    // fxport: one layer of one level of `array` as a 2D texture sharing its texels (a D3D11
    // depth-stencil view of an array slice is a depth buffer over it); `array` must outlive it.
    // `layers` > 1: that many layers from `layer`, a layered depth buffer's texture (draws reach
    // the layer SV_RenderTargetArrayIndex names); read and write texels through `array` then.
    Texture2D(Texture2DArray& array, int layer, int level, int layers = 1);
    // fxport: the same over rows of a 1D texture (`line`'s layers of `level`; one texel high): a
    // D3D11 1D depth-stencil view's depth buffer is made over it. `line` must outlive it.
    Texture2D(Texture1D& line, int layer, int level, int layers = 1);
    // fxport: every level of `source` read as `format`, sharing its texels (a D3D11 shader-resource
    // view of a typeless texture in another format of its family: sRGB of a linear BC1, SNORM of
    // BC4). `format` has `source`'s bytes per texel or block; `source` must outlive it.
    Texture2D(Texture2D& source, SurfaceFormat format);
    ~Texture2D() override;

    int Width() const { return width_; }
    int Height() const { return height_; }
    Rectangle Bounds() const { return Rectangle(0, 0, width_, height_); }

    // T must be the texel type of Format() (Color for Color, float for Single, Vector4 for Vector4,
    // uint16_t[4] packed types for Rgba64/HalfVector4 ...): sizeof(T) * count must equal the bytes of
    // the level (whole level) or of `rect`.
    template <class T> void SetData(const T* data, std::size_t count) { setData(0, nullptr, data, sizeof(T) * count, sizeof(T)); }
    template <class T> void SetData(const std::vector<T>& data) { SetData(data.data(), data.size()); }
    template <class T> void SetData(int level, const Rectangle* rect, const T* data, std::size_t count) {
        setData(level, rect, data, sizeof(T) * count, sizeof(T));
    }
    template <class T> void GetData(T* data, std::size_t count) const { getData(0, data, sizeof(T) * count); }
    template <class T> std::vector<T> GetData() const {
        std::vector<T> out(regionBytes(format_, width_, height_) / sizeof(T));
        GetData(out.data(), out.size());
        return out;
    }

    // Loads a PNG (or any format stb_image reads) as SurfaceFormat::Color. Throws ArgumentError
    // naming the file when it cannot be read.
    static std::unique_ptr<Texture2D> FromFile(fxport::GraphicsDevice& device, const std::string& path);
    // Writes level 0 as an 8-bit RGBA PNG (float formats are clamped to [0,1]; one- and two-channel
    // formats are shown as grey / red-green). Top row first, as the texture is stored.
    void SaveAsPng(const std::string& path) const;
    // SaveAsPng with alpha written as 255 when `opaque`: how SaveBackBufferAsPng saves the frame, which
    // a screen shows without its alpha (XNA's too).
    void savePng(const std::string& path, bool opaque) const;

    void setData(int level, const Rectangle* rect, const void* data, std::size_t bytes, std::size_t elementSize = 1);
    void getData(int level, void* data, std::size_t bytes) const;

protected:
    Texture2D(fxport::GraphicsDevice& device, const char* typeName, int width, int height, bool mipMap,
              SurfaceFormat format);
    // Over a backend texture made elsewhere (a view of another texture's texels), one level.
    Texture2D(fxport::GraphicsDevice& device, const char* typeName, int width, int height, SurfaceFormat format, std::uint32_t adopted);

private:
    void create(bool mipMap);
    int width_;
    int height_;
};

class TextureCube : public Texture {
public:
    TextureCube(fxport::GraphicsDevice& device, int size, bool mipMap = false,
                SurfaceFormat format = SurfaceFormat::Color);
    ~TextureCube() override;

    int Size() const { return size_; }
    template <class T> void SetData(CubeMapFace face, const T* data, std::size_t count) {
        setData(face, data, sizeof(T) * count, sizeof(T));
    }
    template <class T> void GetData(CubeMapFace face, T* data, std::size_t count) const {
        getData(face, data, sizeof(T) * count);
    }
    void setData(CubeMapFace face, const void* data, std::size_t bytes, std::size_t elementSize = 1);
    void getData(CubeMapFace face, void* data, std::size_t bytes) const;
    // One mip level of a face (Size() >> level texels square); ArgumentError for a level outside
    // 0 .. LevelCount() - 1 or a size that does not match (texture_cube_file.cpp).
    template <class T> void SetData(CubeMapFace face, int level, const T* data, std::size_t count) {
        setData(face, level, data, sizeof(T) * count, sizeof(T));
    }
    template <class T> void GetData(CubeMapFace face, int level, T* data, std::size_t count) const {
        getData(face, level, data, sizeof(T) * count);
    }
    void setData(CubeMapFace face, int level, const void* data, std::size_t bytes, std::size_t elementSize = 1);
    void getData(CubeMapFace face, int level, void* data, std::size_t bytes) const;

    // fxport: a .dds cube map (what XNA's content pipeline loads as TextureCube): its six faces and
    // mip levels as stored (a partial chain completed by 2x2 averages), BC1-BC3 decoded to
    // SurfaceFormat::Color as Texture2D::FromFile does (dds_image.h). Throws ArgumentError naming
    // the file for a 2D texture, a cube whose faces are not square, or what readDds refuses.
    static std::unique_ptr<TextureCube> FromFile(fxport::GraphicsDevice& device, const std::string& path);

protected:
    TextureCube(fxport::GraphicsDevice& device, const char* typeName, int size, bool mipMap, SurfaceFormat format);

private:
    void create(bool mipMap);
    int size_;
};

}  // namespace fxport
