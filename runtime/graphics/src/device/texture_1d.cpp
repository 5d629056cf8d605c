#include "fxport/graphics/texture_1d.h"

#include "device/device_impl.h"
#include "fxport/graphics/render_target.h"
#include "fxport/graphics/errors.h"

namespace fxport {

namespace {

// D3D11's widest 1D texture and largest 1D array (D3D11_REQ_TEXTURE1D_U_DIMENSION,
// D3D11_REQ_TEXTURE1D_ARRAY_AXIS_DIMENSION); GL 4.5 guarantees 16384 texels and 2048 layers.
constexpr int kMaxWidth = 16384;
constexpr int kMaxLayers = 2048;

int fullChain(int width) {
    int levels = 1;
    for (int size = width; size > 1; size /= 2) ++levels;
    return levels;
}

std::string range(int first, int count) { return "[" + std::to_string(first) + ", " + std::to_string(first + count) + ")"; }

Texture::Kind kindOf(bool array) { return array ? Texture::Kind::Texture1DArray : Texture::Kind::Texture1D; }
const char* typeNameOf(bool array) { return array ? "Texture1DArray" : "Texture1D"; }

}  // namespace

Texture1D::Texture1D(fxport::GraphicsDevice& device, int width, int layers, int levels, SurfaceFormat format, bool array)
    : Texture(device, typeNameOf(array), kindOf(array), format, levels), width_(width), layers_(layers) {
    if (width <= 0 || width > kMaxWidth)
        throw ArgumentError(describe() + ": width " + std::to_string(width) + " is outside 1.." + std::to_string(kMaxWidth));
    if (layers <= 0 || layers > kMaxLayers || (!array && layers != 1))
        throw ArgumentError(describe() + ": " + std::to_string(layers) + " layers (" + (array ? "1 to 2048" : "a plain 1D texture has 1") + ")");
    if (levels <= 0 || levels > fullChain(width))
        throw ArgumentError(describe() + ": " + std::to_string(levels) + " levels (" + std::to_string(width) + " texels wide has 1 to " +
                            std::to_string(fullChain(width)) + ")");
    if (isCompressedFormat(format)) throw ArgumentError(describe() + ": " + surfaceFormatName(format) + " (block-compressed formats are 2D and 3D only)");
    name_ = deviceImpl(device).createLineTexture(format_, levels_, width_, layers_, array);
}

Texture1D::Texture1D(Texture1D& source, int firstLevel, int levels, int firstLayer, int layers, bool array)
    : Texture(source.device(), typeNameOf(array), kindOf(array), source.Format(), levels), width_(source.levelWidth(firstLevel < 0 ? 0 : firstLevel)),
      layers_(layers) {
    if (firstLevel < 0 || levels <= 0 || firstLevel + levels > source.LevelCount() || firstLayer < 0 || layers <= 0 ||
        firstLayer + layers > source.Layers() || (!array && layers != 1))
        throw ArgumentError(describe() + ": a view of levels " + range(firstLevel, levels) + " and layers " + range(firstLayer, layers) + " of " +
                            source.describe() + ", which has " + std::to_string(source.LevelCount()) + " levels and " +
                            std::to_string(source.Layers()) + " layers");
    name_ = deviceImpl(device()).createTextureView(describe(), source.backendObject(), format_, array, firstLevel, levels, firstLayer, layers);
}

Texture1D::~Texture1D() { disposeFromDestructor(); }

std::uint32_t Texture1D::rowView(const char* who, int layer, int level, int layers) {
    checkSubresource(who, level, layer);
    if (layers < 1 || layers > layers_ - layer)
        throw ArgumentError(describe() + ": " + who + ": layers " + range(layer, layers) + " of " + std::to_string(layers_));
    return deviceImpl(device()).createTextureView(describe() + ": " + who, name_, format_, layers > 1, level, 1, layer, layers);
}

// A framebuffer takes a 1D texture as an image one row high (and a 1D array layered), so the 2D
// target and depth paths draw into rows unchanged.
Texture2D::Texture2D(Texture1D& line, int layer, int level, int layers)
    : Texture2D(line.device(), "Texture2D", line.levelWidth(level), 1, line.Format(), line.rowView("a Texture2D over rows", layer, level, layers)) {}

RenderTarget2D::RenderTarget2D(Texture1D& line, int layer, int level, int layers)
    : RenderTarget2D(line.device(), line.levelWidth(level), line.Format(), line.rowView("a RenderTarget2D over rows", layer, level, layers)) {}

std::size_t Texture1D::rowBytes(int level) const { return regionBytes(format_, levelWidth(level), 1); }

void Texture1D::checkSubresource(const char* call, int level, int layer) const {
    if (level < 0 || level >= levels_ || layer < 0 || layer >= layers_)
        throw ArgumentError(describe() + ": " + call + " level " + std::to_string(level) + " of " + std::to_string(levels_) + ", layer " +
                            std::to_string(layer) + " of " + std::to_string(layers_));
}

void Texture1D::setData(int level, int layer, int x, int count, const void* data, std::size_t bytes) {
    throwIfDisposed("SetData");
    checkSubresource("SetData", level, layer);
    const int w = levelWidth(level);
    if (x < 0 || count <= 0 || x + count > w)
        throw ArgumentError(describe() + ": SetData texels " + range(x, count) + " are outside level " + std::to_string(level) + " (" +
                            std::to_string(w) + " wide)");
    writeTexels(face(layer), level, x, 0, count, 1, data, bytes);
}

void Texture1D::getData(int level, int layer, void* data, std::size_t bytes) const {
    throwIfDisposed("GetData");
    checkSubresource("GetData", level, layer);
    if (bytes != rowBytes(level))
        throw ArgumentError(describe() + ": GetData buffer has " + std::to_string(bytes) + " bytes, a row of level " + std::to_string(level) +
                            " has " + std::to_string(rowBytes(level)));
    readTexels(face(layer), level, data, bytes);
}

}  // namespace fxport
