// TextureCube's per-level data and its .dds loader (texture.h). The faces come decoded from
// dds_image.cpp; the upload is Texture::writeTexels, as for every texture.
#include <algorithm>
#include <string>
#include <vector>

#include "device/dds_image.h"
#include "device/image_io.h"
#include "device/surface_formats.h"
#include "fxport/graphics/errors.h"
#include "fxport/graphics/texture.h"

namespace fxport {

void TextureCube::setData(CubeMapFace face, int level, const void* data, std::size_t bytes, std::size_t elementSize) {
    throwIfDisposed("SetData");
    if (level < 0 || level >= levels_)
        throw ArgumentError(describe() + ": SetData level " + std::to_string(level) + " (the cube has " + std::to_string(levels_) + " levels)");
    const int size = levelWidth(size_, level);
    writeTexels(int(face), level, 0, 0, size, size, data, bytes, elementSize);
}

void TextureCube::getData(CubeMapFace face, int level, void* data, std::size_t bytes) const {
    throwIfDisposed("GetData");
    if (level < 0 || level >= levels_)
        throw ArgumentError(describe() + ": GetData level " + std::to_string(level) + " (the cube has " + std::to_string(levels_) + " levels)");
    const int size = levelWidth(size_, level);
    const std::size_t expected = regionBytes(format_, size, size);
    if (bytes != expected)
        throw ArgumentError(describe() + ": GetData buffer has " + std::to_string(bytes) + " bytes, level " + std::to_string(level) + " of a face has " +
                            std::to_string(expected));
    readTexels(int(face), level, data, bytes);
}

std::unique_ptr<TextureCube> TextureCube::FromFile(fxport::GraphicsDevice& device, const std::string& path) {
    detail::DdsImage dds = detail::readDds(path);  // throws ArgumentError naming the file
    if (!dds.cube)
        throw ArgumentError("TextureCube::FromFile: '" + path + "' is not a cube map (" + (dds.volume ? "a volume texture; load it as Texture3D" : "a 2D texture; load it as Texture2D") + ")");
    if (dds.width != dds.height)
        throw ArgumentError("TextureCube::FromFile: '" + path + "' has " + std::to_string(dds.width) + "x" + std::to_string(dds.height) +
                            " faces; a cube's are square");
    auto cube = std::make_unique<TextureCube>(device, dds.width, dds.levelCount > 1, SurfaceFormat::Color);
    cube->Name = path;
    for (int face = 0; face < 6; ++face) {
        std::vector<Color> level;
        for (int l = 0; l < cube->LevelCount(); ++l) {
            const int size = std::max(1, dds.width >> l);
            if (l < dds.levelCount) level = std::move(dds.levels[std::size_t(face * dds.levelCount + l)]);
            else level = detail::halve(level, std::max(1, dds.width >> (l - 1)), std::max(1, dds.width >> (l - 1)));
            cube->SetData(CubeMapFace(face), l, level.data(), std::size_t(size) * std::size_t(size));
        }
    }
    return cube;
}

}  // namespace fxport
