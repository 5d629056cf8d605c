#include "fxport/graphics/texture_3d.h"

#include <algorithm>

#include "device/device_impl.h"
#include "fxport/graphics/errors.h"

namespace fxport {

namespace {

// D3D11's largest volume (D3D11_REQ_TEXTURE3D_U_V_OR_W_DIMENSION), which is also the least
// GL_MAX_3D_TEXTURE_SIZE GL 4.5 guarantees: no driver query is needed.
constexpr int kMaxVolumeSize = 2048;

int levelsFor(int width, int height, int depth) {
    int levels = 1;
    for (int size = std::max({width, height, depth}); size > 1; size /= 2) ++levels;
    return levels;
}

}  // namespace

Texture3D::Texture3D(fxport::GraphicsDevice& device, int width, int height, int depth, bool mipMap, SurfaceFormat format)
    : Texture(device, "Texture3D", Kind::Texture3D, format, mipMap ? levelsFor(width, height, depth) : 1),
      width_(width), height_(height), depth_(depth) {
    if (width <= 0 || height <= 0 || depth <= 0 || width > kMaxVolumeSize || height > kMaxVolumeSize || depth > kMaxVolumeSize)
        throw ArgumentError("Texture3D: size " + std::to_string(width) + "x" + std::to_string(height) + "x" + std::to_string(depth) +
                            " is outside 1.." + std::to_string(kMaxVolumeSize) + " in some dimension");
    name_ = deviceImpl(device).createVolumeTexture(format_, levels_, width_, height_, depth_);
}

Texture3D::~Texture3D() { disposeFromDestructor(); }

std::size_t Texture3D::levelBytes(int level) const {
    return regionBytes(format_, levelWidth(width_, level), levelWidth(height_, level)) * std::size_t(levelWidth(depth_, level));
}

void Texture3D::checkLevel(const char* call, int level) const {
    if (level < 0 || level >= levels_)
        throw ArgumentError(describe() + ": " + call + " level " + std::to_string(level) + " of " + std::to_string(levels_));
}

void Texture3D::setData(int level, const void* data, std::size_t bytes, std::size_t elementSize) {
    throwIfDisposed("SetData");
    checkLevel("SetData", level);
    const std::size_t expected = levelBytes(level);
    if (bytes != expected)
        throw ArgumentError(describe() + ": SetData got " + std::to_string(bytes / std::max<std::size_t>(elementSize, 1)) +
                            (elementSize > 1 ? " elements of " + std::to_string(elementSize) + " bytes" : std::string(" bytes")) + ", level " +
                            std::to_string(level) + " (" + std::to_string(levelWidth(width_, level)) + "x" + std::to_string(levelWidth(height_, level)) +
                            "x" + std::to_string(levelWidth(depth_, level)) + " " + surfaceFormatName(format_) + ") needs " +
                            std::to_string(expected) + " bytes");
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.storageBarrier();  // after a shader's image writes, before this upload
    d.backend->writeVolume(name_, format_, level, levelWidth(width_, level), levelWidth(height_, level), levelWidth(depth_, level), data);
}

void Texture3D::getData(int level, void* data, std::size_t bytes) const {
    throwIfDisposed("GetData");
    checkLevel("GetData", level);
    if (bytes != levelBytes(level))
        throw ArgumentError(describe() + ": GetData buffer has " + std::to_string(bytes) + " bytes, level " + std::to_string(level) + " has " +
                            std::to_string(levelBytes(level)));
    readTexels(-1, level, data, bytes);
}

}  // namespace fxport
