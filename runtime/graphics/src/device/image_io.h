// INTERNAL: PNG (and other stb_image formats) in and out, 8-bit RGBA, top row first.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "fxport/math.h"

namespace fxport::detail {

struct Image {
    int width = 0;
    int height = 0;
    std::vector<Color> pixels;
};

// Throws ArgumentError naming the file and stb's reason.
Image loadImage(const std::string& path);
// Throws std::runtime_error naming the file when it cannot be written.
void savePng(const std::string& path, int width, int height, const std::uint8_t* rgba);

}  // namespace fxport::detail
