#include "device/image_io.h"

#include <climits>
#include <cstring>
#include <stdexcept>

#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include "fxport/graphics/errors.h"
#include "fxport/platform/file_reading.h"

namespace fxport::detail {

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
