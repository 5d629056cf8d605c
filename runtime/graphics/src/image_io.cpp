#include "image_io.h"

#include <cstring>
#include <stdexcept>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "fxport/graphics/errors.h"

namespace fxport::detail {

Image loadImage(const std::string& path) {
    int w = 0, h = 0, channels = 0;
    stbi_uc* data = stbi_load(path.c_str(), &w, &h, &channels, 4);
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
