#include "image.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <stb/stb_image_write.h>

namespace fxport::content {

std::uint8_t ToByte(float value) {
    const float clamped = std::clamp(value, 0.0f, 1.0f);
    return static_cast<std::uint8_t>(std::lround(clamped * 255.0f));
}

Image::Image(int width, int height)
    : width_(width), height_(height),
      pixels_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4, 0) {}

void Image::Set(int x, int y, Rgba c) {
    const std::size_t o = Offset(x, y);
    pixels_[o + 0] = ToByte(c.r);
    pixels_[o + 1] = ToByte(c.g);
    pixels_[o + 2] = ToByte(c.b);
    pixels_[o + 3] = ToByte(c.a);
}

HeightField::HeightField(int width, int height)
    : width_(width), height_(height),
      values_(static_cast<std::size_t>(width) * static_cast<std::size_t>(height), 0.0f) {}

std::size_t HeightField::Index(int x, int y) const {
    const int wx = ((x % width_) + width_) % width_;
    const int wy = ((y % height_) + height_) % height_;
    return static_cast<std::size_t>(wy) * static_cast<std::size_t>(width_) + static_cast<std::size_t>(wx);
}

void WritePng(const Image& image, const std::filesystem::path& path) {
    const int ok = stbi_write_png(path.string().c_str(), image.Width(), image.Height(), 4,
                                  image.Pixels().data(), image.Width() * 4);
    if (ok == 0) {
        throw std::runtime_error("cannot write " + path.string());
    }
}

}  // namespace fxport::content
