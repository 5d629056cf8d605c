// RGBA8 images (what every PNG the tool writes is) and a float height field used while generating
// them. Rows are stored top row first, as PNG stores them and as D3D/XNA/glTF texture
// coordinates address them (v = 0 is the top row).
#pragma once

#include <cstdint>
#include <filesystem>
#include <vector>

namespace fxport::content {

// A colour with float channels in [0, 1]; quantised to 8 bits when stored.
struct Rgba {
    float r = 0, g = 0, b = 0, a = 1;
};

// Rounds a [0, 1] value to 0..255 (0.5 -> 128, so a flat normal encodes as (128, 128, 255)).
std::uint8_t ToByte(float value);

class Image {
public:
    Image(int width, int height);

    int Width() const { return width_; }
    int Height() const { return height_; }
    void Set(int x, int y, Rgba c);
    // Channel c (0 = R .. 3 = A) of pixel (x, y), as stored.
    std::uint8_t At(int x, int y, int c) const { return pixels_[Offset(x, y) + static_cast<std::size_t>(c)]; }
    const std::vector<std::uint8_t>& Pixels() const { return pixels_; }

private:
    std::size_t Offset(int x, int y) const {
        return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(x)) * 4;
    }
    int width_;
    int height_;
    std::vector<std::uint8_t> pixels_;
};

// A scalar per pixel; reads wrap around, so derivatives of tileable fields stay tileable.
class HeightField {
public:
    HeightField(int width, int height);

    int Width() const { return width_; }
    int Height() const { return height_; }
    float& At(int x, int y) { return values_[Index(x, y)]; }
    float At(int x, int y) const { return values_[Index(x, y)]; }

private:
    std::size_t Index(int x, int y) const;
    int width_;
    int height_;
    std::vector<float> values_;
};

// Writes `image` as an 8-bit RGBA PNG (stb_image_write; its deflate is deterministic). Throws
// std::runtime_error when the file cannot be written.
void WritePng(const Image& image, const std::filesystem::path& path);

}  // namespace fxport::content
