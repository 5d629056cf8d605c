#include "device/image_io.h"

#include <algorithm>
#include <climits>
#include <cstring>
#include <stdexcept>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "fxport/graphics/errors.h"
#include "fxport/platform/file_reading.h"

namespace fxport::detail {

std::vector<Color> halve(const std::vector<Color>& level, int width, int height) {
    const int w = std::max(1, width / 2), h = std::max(1, height / 2);
    std::vector<Color> out(std::size_t(w) * std::size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            int sum[4] = {0, 0, 0, 0}, n = 0;
            for (int dy = 0; dy < 2; ++dy)
                for (int dx = 0; dx < 2; ++dx) {
                    const int sx = std::min(2 * x + dx, width - 1), sy = std::min(2 * y + dy, height - 1);
                    const Color& c = level[std::size_t(sy) * std::size_t(width) + std::size_t(sx)];
                    sum[0] += c.R, sum[1] += c.G, sum[2] += c.B, sum[3] += c.A, ++n;
                }
            out[std::size_t(y) * std::size_t(w) + std::size_t(x)] = Color((sum[0] + n / 2) / n, (sum[1] + n / 2) / n, (sum[2] + n / 2) / n, (sum[3] + n / 2) / n);
        }
    return out;
}

Image loadImage(const std::string& path) {
    int w = 0, h = 0, channels = 0;
    platform::FileBytes file = platform::readUntrustedFile(path);
    if (!file.ok()) throw ArgumentError("Texture2D::FromFile: " + file.error);
    if (file.bytes.size() > std::size_t(INT_MAX)) throw ArgumentError("Texture2D::FromFile: '" + path + "' is too large");
    stbi_uc* data = stbi_load_from_memory(file.bytes.data(), int(file.bytes.size()), &w, &h, &channels, 4);
    if (!data)
        throw ArgumentError("Texture2D::FromFile: cannot read '" + path + "': " +
                            (stbi_failure_reason() ? stbi_failure_reason() : "unknown error"));
    Image image;
    image.width = w;
    image.height = h;
    image.pixels.resize(std::size_t(w) * std::size_t(h));
    std::memcpy(image.pixels.data(), data, image.pixels.size() * 4);
    stbi_image_free(data);
    return image;
}

void savePng(const std::string& path, int width, int height, const std::uint8_t* rgba) {
    if (!stbi_write_png(path.c_str(), width, height, 4, rgba, width * 4))
        throw std::runtime_error("cannot write PNG '" + path + "'");
}

}  // namespace fxport::detail
