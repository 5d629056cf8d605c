#include "fxport/graphics/texture.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "device/dds_image.h"
#include "device/device_impl.h"
#include "effect/effect_notices.h"
#include "fxport/graphics/errors.h"
#include "device/image_io.h"
#include "device/surface_formats.h"

namespace fxport {

namespace {

int mipLevelsFor(int size) {
    int levels = 1;
    while (size > 1) {
        size /= 2;
        ++levels;
    }
    return levels;
}

void checkSize(fxport::GraphicsDevice& device, const char* type, int width, int height) {
    int limit = device.maxTextureSize();
    if (width <= 0 || height <= 0 || width > limit || height > limit)
        throw ArgumentError(std::string(type) + ": size " + std::to_string(width) + "x" + std::to_string(height) +
                            " is outside 1.." + std::to_string(limit) + " (the driver's GL_MAX_TEXTURE_SIZE)");
}

}  // namespace

Texture::Texture(fxport::GraphicsDevice& device, const char* typeName, Kind kind, SurfaceFormat format, int levels)
    : GraphicsResource(device, typeName), format_(format), levels_(levels), kind_(kind) {}

void Texture::releaseGpuObjects() {
    GraphicsDevice::Impl& d = deviceImpl(device());
    for (int slot = 0; slot < kMaxTextureSlots; ++slot) {
        if (device().Textures[slot].get() == this) device().Textures[slot] = nullptr;
        if (device().VertexTextures[slot].get() == this) device().VertexTextures[slot] = nullptr;
    }
    for (Effect* effect : d.effects) forgetTexture(*effect, this);
    d.forgetStorage(this);
    d.forgetSampleCopy(this);
    d.dropFramebuffersUsing(name_);
    d.deleteTexture(name_);
}

int Texture::levelWidth(int base, int level) const { return std::max(1, base >> level); }

// D3D's rule for compressed formats, which GL shares: a region starts on the 4-texel grid and ends on
// it or at the level's edge.
void Texture::checkBlockGrid(const Rectangle& r, int levelWidth, int levelHeight) const {
    if (!isCompressedFormat(format_)) return;
    const int x = r.X, y = r.Y, w = r.Width, h = r.Height;
    const bool xEnds = (x + w) % 4 == 0 || x + w == levelWidth, yEnds = (y + h) % 4 == 0 || y + h == levelHeight;
    if (x % 4 != 0 || y % 4 != 0 || !xEnds || !yEnds)
        throw ArgumentError(describe() + ": SetData region (" + std::to_string(x) + "," + std::to_string(y) + "," + std::to_string(w) + "," +
                            std::to_string(h) + ") of " + surfaceFormatName(format_) +
                            " is not on the 4x4 block grid (corners at multiples of 4 or the level's edge)");
}

void Texture::writeTexels(int face, int level, int x, int y, int w, int h, const void* data, std::size_t bytes, std::size_t elementSize) {
    if (samples_ > 0) throw InvalidOperation(describe() + ": SetData on a multisampled texture (its samples are written by draws only)");
    std::size_t expected = regionBytes(format_, w, h);
    if (bytes != expected) {
        // In the caller's units: SetData(data, count) counts elements, not bytes.
        const std::string unit = elementSize > 1 ? " elements of " + std::to_string(elementSize) + " bytes" : " bytes";
        const std::string needs = elementSize > 1 && expected % elementSize == 0 ? std::to_string(expected / elementSize) + unit
                                                                                  : std::to_string(expected) + " bytes";
        throw ArgumentError(describe() + ": SetData got " + std::to_string(bytes / std::max<std::size_t>(elementSize, 1)) + unit +
                            ", the region " + std::to_string(w) + "x" + std::to_string(h) + " of " + surfaceFormatName(format_) +
                            " needs " + needs);
    }
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.storageBarrier();  // after a shader's image writes, before this upload
    d.backend->writeTexture(name_, format_, face, level, Rectangle(x, y, w, h), data);
}

void Texture::readTexels(int face, int level, void* data, std::size_t bytes) const {
    if (samples_ > 0) throw InvalidOperation(describe() + ": GetData on a multisampled texture (resolve it into a single-sample one first)");
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.resolvePendingClearBeforeRead(this);
    d.backend->readTexture(name_, format_, face, level, bytes, data);
}

// --- Texture2D

Texture2D::Texture2D(fxport::GraphicsDevice& device, int width, int height, bool mipMap, SurfaceFormat format)
    : Texture2D(device, "Texture2D", width, height, mipMap, format) {}

Texture2D::Texture2D(fxport::GraphicsDevice& device, const char* typeName, int width, int height, bool mipMap,
                     SurfaceFormat format)
    : Texture(device, typeName, Kind::Texture2D, format, mipMap ? mipLevelsFor(std::max(width, height)) : 1),
      width_(width), height_(height) {
    checkSize(device, typeName, width, height);
    create(mipMap);
}

Texture2D::Texture2D(fxport::GraphicsDevice& device, const char* typeName, int width, int height, SurfaceFormat format, std::uint32_t adopted)
    : Texture(device, typeName, Kind::Texture2D, format, 1), width_(width), height_(height) {
    name_ = adopted;
}

Texture2D::Texture2D(Texture2D& source, SurfaceFormat format)
    : Texture(source.device(), "Texture2D", Kind::Texture2D, format, source.LevelCount()), width_(source.Width()), height_(source.Height()) {
    name_ = deviceImpl(device()).createTextureView(describe() + " as " + surfaceFormatName(format), source.backendObject(), format, false, 0,
                                                   levels_, 0, 1);
}

void Texture2D::create(bool) {
    name_ = deviceImpl(device()).createTexture(false, format_, levels_, width_, height_);
}

Texture2D::~Texture2D() { disposeFromDestructor(); }

void Texture2D::setData(int level, const Rectangle* rect, const void* data, std::size_t bytes, std::size_t elementSize) {
    throwIfDisposed("SetData");
    if (level < 0 || level >= levels_)
        throw ArgumentError(describe() + ": SetData level " + std::to_string(level) + " of " + std::to_string(levels_));
    int w = levelWidth(width_, level), h = levelWidth(height_, level);
    Rectangle r = rect ? *rect : Rectangle(0, 0, w, h);
    if (r.X < 0 || r.Y < 0 || r.Width <= 0 || r.Height <= 0 || r.X + r.Width > w || r.Y + r.Height > h)
        throw ArgumentError(describe() + ": SetData rectangle (" + std::to_string(r.X) + "," + std::to_string(r.Y) + "," +
                            std::to_string(r.Width) + "," + std::to_string(r.Height) + ") is outside the " +
                            std::to_string(w) + "x" + std::to_string(h) + " level");
    checkBlockGrid(r, w, h);
    writeTexels(-1, level, r.X, r.Y, r.Width, r.Height, data, bytes, elementSize);
}

void Texture2D::getData(int level, void* data, std::size_t bytes) const {
    throwIfDisposed("GetData");
    int w = levelWidth(width_, level), h = levelWidth(height_, level);
    std::size_t expected = regionBytes(format_, w, h);
    if (bytes != expected)
        throw ArgumentError(describe() + ": GetData buffer has " + std::to_string(bytes) + " bytes, level " +
                            std::to_string(level) + " (" + std::to_string(w) + "x" + std::to_string(h) + " " +
                            surfaceFormatName(format_) + ") has " + std::to_string(expected));
    readTexels(-1, level, data, bytes);
}

namespace detail {

// A DDS file's levels as stored (decoded to RGBA8); a partial mip chain is completed by averaging
// 2x2 texels, as GenerateMips would.
std::unique_ptr<Texture2D> texture2DFromDds(fxport::GraphicsDevice& device, const std::string& path) {
    detail::DdsImage dds = detail::readDds(path);
    if (dds.cube) throw ArgumentError("Texture2D::FromFile: '" + path + "' is a cube map (six faces); a Texture2D has one");
    if (dds.volume) throw ArgumentError("Texture2D::FromFile: '" + path + "' is a volume texture (depth " + std::to_string(dds.depth) + "); load it as Texture3D");
    auto texture = std::make_unique<Texture2D>(device, dds.width, dds.height, dds.levelCount > 1, SurfaceFormat::Color);
    texture->Name = path;
    std::vector<Color> level;
    for (int l = 0; l < texture->LevelCount(); ++l) {
        const int w = std::max(1, dds.width >> l), h = std::max(1, dds.height >> l);
        if (l < dds.levelCount) level = std::move(dds.levels[std::size_t(l)]);
        else level = detail::halve(level, std::max(1, dds.width >> (l - 1)), std::max(1, dds.height >> (l - 1)));
        texture->SetData(l, nullptr, level.data(), std::size_t(w) * std::size_t(h));
    }
    return texture;
}

}  // namespace detail

std::unique_ptr<Texture2D> Texture2D::FromFile(fxport::GraphicsDevice& device, const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (extension == ".dds") return detail::texture2DFromDds(device, path);
    detail::Image image = detail::loadImage(path);  // throws ArgumentError naming the file
    auto texture = std::make_unique<Texture2D>(device, image.width, image.height, false, SurfaceFormat::Color);
    texture->Name = path;
    texture->SetData(image.pixels.data(), image.pixels.size());
    return texture;
}

void Texture2D::SaveAsPng(const std::string& path) const { savePng(path, false); }

void Texture2D::savePng(const std::string& path, bool opaque) const {
    throwIfDisposed("SaveAsPng");
    const int channels = channelCount(format_);
    // Read back as floats in the backend's RGBA expansion, then quantise: one path for every format.
    std::vector<float> texels(std::size_t(width_) * std::size_t(height_) * 4);
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.resolvePendingClearBeforeRead(this);
    d.backend->readTextureFloats(name_, -1, 0, texels.size() * sizeof(float), texels.data());
    std::vector<std::uint8_t> rgba(texels.size());
    for (std::size_t i = 0; i < texels.size(); i += 4) {
        float c[4] = {texels[i], texels[i + 1], texels[i + 2], texels[i + 3]};
        if (channels == 1) c[1] = c[2] = c[0], c[3] = 1;  // grey
        if (channels == 2) c[2] = 0, c[3] = 1;
        if (format_ == SurfaceFormat::Alpha8) c[0] = c[1] = c[2] = c[3] = texels[i];
        if (opaque) c[3] = 1;
        for (int k = 0; k < 4; ++k) {
            float v = std::isfinite(c[k]) ? std::clamp(c[k], 0.0f, 1.0f) : 0.0f;
            rgba[i + std::size_t(k)] = std::uint8_t(std::lround(v * 255.0f));
        }
    }
    detail::savePng(path, width_, height_, rgba.data());
}

// --- TextureCube

TextureCube::TextureCube(fxport::GraphicsDevice& device, int size, bool mipMap, SurfaceFormat format)
    : TextureCube(device, "TextureCube", size, mipMap, format) {}

TextureCube::TextureCube(fxport::GraphicsDevice& device, const char* typeName, int size, bool mipMap,
                         SurfaceFormat format)
    : Texture(device, typeName, Kind::TextureCube, format, mipMap ? mipLevelsFor(size) : 1), size_(size) {
    checkSize(device, typeName, size, size);
    create(mipMap);
}

void TextureCube::create(bool) {
    name_ = deviceImpl(device()).createTexture(true, format_, levels_, size_, size_);
}

TextureCube::~TextureCube() { disposeFromDestructor(); }

void TextureCube::setData(CubeMapFace face, const void* data, std::size_t bytes, std::size_t elementSize) {
    throwIfDisposed("SetData");
    writeTexels(int(face), 0, 0, 0, size_, size_, data, bytes, elementSize);
}

void TextureCube::getData(CubeMapFace face, void* data, std::size_t bytes) const {
    throwIfDisposed("GetData");
    std::size_t expected = regionBytes(format_, size_, size_);
    if (bytes != expected)
        throw ArgumentError(describe() + ": GetData buffer has " + std::to_string(bytes) + " bytes, a face has " +
                            std::to_string(expected));
    readTexels(int(face), 0, data, bytes);
}

}  // namespace fxport
