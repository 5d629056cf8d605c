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

// The next mip level of a width x height level: each texel the rounded average of the 2x2 texels
// above it, an odd edge repeating its last row/column (a side of 1 stays 1).
std::vector<Color> halve(const std::vector<Color>& level, int width, int height);

// Throws ArgumentError naming the file and stb's reason.
Image loadImage(const std::string& path);
// Throws std::runtime_error naming the file when it cannot be written.
void savePng(const std::string& path, int width, int height, const std::uint8_t* rgba);

}  // namespace fxport::detail
