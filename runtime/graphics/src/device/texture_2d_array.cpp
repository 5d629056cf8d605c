#include "fxport/graphics/texture_2d_array.h"

#include <algorithm>

#include "device/device_impl.h"
#include "fxport/graphics/errors.h"

namespace fxport {

namespace {

// D3D11's largest array (D3D11_REQ_TEXTURE2D_ARRAY_AXIS_DIMENSION), which is also the least
// GL_MAX_ARRAY_TEXTURE_LAYERS GL 4.5 guarantees (2048): no driver query is needed.
constexpr int kMaxLayers = 2048;

int fullChain(int width, int height) {
    int levels = 1;
    for (int size = std::max(width, height); size > 1; size /= 2) ++levels;
    return levels;
}

std::string range(int first, int count) { return "[" + std::to_string(first) + ", " + std::to_string(first + count) + ")"; }

}  // namespace

Texture2DArray::Texture2DArray(fxport::GraphicsDevice& device, int width, int height, int layers, int levels, SurfaceFormat format)
    : Texture(device, "Texture2DArray", Kind::Texture2DArray, format, levels), width_(width), height_(height), layers_(layers) {
    const int limit = deviceImpl(device).backend->maxTextureSize();
    if (width <= 0 || height <= 0 || width > limit || height > limit)
        throw ArgumentError("Texture2DArray: size " + std::to_string(width) + "x" + std::to_string(height) + " is outside 1.." + std::to_string(limit));
    if (layers <= 0 || layers > kMaxLayers)
        throw ArgumentError("Texture2DArray: " + std::to_string(layers) + " layers (1 to " + std::to_string(kMaxLayers) + ")");
    if (levels <= 0 || levels > fullChain(width, height))
        throw ArgumentError("Texture2DArray: " + std::to_string(levels) + " levels (a " + std::to_string(width) + "x" + std::to_string(height) +
                            " array has 1 to " + std::to_string(fullChain(width, height)) + ")");
    name_ = deviceImpl(device).createArrayTexture(format_, levels_, width_, height_, layers_);
}

Texture2DArray::Texture2DArray(Texture2DArray& source, int firstLevel, int levels, int firstLayer, int layers)
    : Texture(source.device(), "Texture2DArray", Kind::Texture2DArray, source.Format(), levels),
      width_(source.levelWidth(std::max(firstLevel, 0))), height_(source.levelHeight(std::max(firstLevel, 0))), layers_(layers) {
    if (firstLevel < 0 || levels <= 0 || firstLevel + levels > source.LevelCount() || firstLayer < 0 || layers <= 0 ||
        firstLayer + layers > source.Layers())
        throw ArgumentError(describe() + ": a view of levels " + range(firstLevel, levels) + " and layers " + range(firstLayer, layers) + " of " +
                            source.describe() + ", which has " + std::to_string(source.LevelCount()) + " levels and " +
                            std::to_string(source.Layers()) + " layers");
    name_ = deviceImpl(device()).createTextureView(describe(), source.backendObject(), format_, true, firstLevel, levels, firstLayer, layers);
    samples_ = source.samples_;  // a view of a multisampled array (core::MultisampleArray) is one too
}

Texture2DArray::Texture2DArray(Texture2DArray& source, int firstLevel, int levels, Cubes cubes)
    : Texture(source.device(), "TextureCubeArray", Kind::TextureCubeArray, source.Format(), levels),
      width_(source.levelWidth(std::max(firstLevel, 0))), height_(source.levelHeight(std::max(firstLevel, 0))), layers_(6 * cubes.cubes) {
    if (firstLevel < 0 || levels <= 0 || firstLevel + levels > source.LevelCount() || cubes.firstLayer < 0 || cubes.cubes <= 0 ||
        cubes.firstLayer + layers_ > source.Layers() || source.Width() != source.Height())
        throw ArgumentError(describe() + ": " + std::to_string(cubes.cubes) + " cubes from layer " + std::to_string(cubes.firstLayer) + ", levels " +
                            range(firstLevel, levels) + " of " + source.describe() + " (" + std::to_string(source.Width()) + "x" +
                            std::to_string(source.Height()) + ", " + std::to_string(source.LevelCount()) + " levels, " +
                            std::to_string(source.Layers()) + " layers; cubes are square)");
    name_ = deviceImpl(device()).backend->createCubeArrayView(source.backendObject(), format_, firstLevel, levels, cubes.firstLayer, layers_);
    if (name_ == 0) throw InvalidOperation(describe() + ": the graphics API could not make a cube map array view");
    ++deviceImpl(device()).live.textures;  // deleted as any texture view is
}

Texture2DArray::~Texture2DArray() { disposeFromDestructor(); }

std::uint32_t Texture2DArray::layerView(const char* who, int layer, int level, int layers) {
    checkSubresource(who, level, layer);
    if (layers < 1 || layers > layers_ - layer)
        throw ArgumentError(describe() + ": " + who + ": layers " + range(layer, layers) + " of " + std::to_string(layers_));
    return deviceImpl(device()).createTextureView(describe() + ": " + who, name_, format_, layers > 1, level, 1, layer, layers);
}

Texture2D::Texture2D(Texture2DArray& array, int layer, int level, int layers)
    : Texture2D(array.device(), "Texture2D", array.levelWidth(level), array.levelHeight(level), array.Format(),
                array.layerView("a Texture2D over layers", layer, level, layers)) {
    samples_ = array.sampleCount();
}

std::size_t Texture2DArray::layerBytes(int level) const {
    return regionBytes(format_, levelWidth(level), levelHeight(level));
}

void Texture2DArray::checkSubresource(const char* call, int level, int layer) const {
    if (level < 0 || level >= levels_ || layer < 0 || layer >= layers_)
        throw ArgumentError(describe() + ": " + call + " level " + std::to_string(level) + " of " + std::to_string(levels_) + ", layer " +
                            std::to_string(layer) + " of " + std::to_string(layers_));
}

void Texture2DArray::setData(int level, int layer, const Rectangle* rect, const void* data, std::size_t bytes) {
    throwIfDisposed("SetData");
    checkSubresource("SetData", level, layer);
    const int w = levelWidth(level), h = levelHeight(level);
    const Rectangle r = rect ? *rect : Rectangle(0, 0, w, h);
    if (r.X < 0 || r.Y < 0 || r.Width <= 0 || r.Height <= 0 || r.X + r.Width > w || r.Y + r.Height > h)
        throw ArgumentError(describe() + ": SetData rectangle (" + std::to_string(r.X) + "," + std::to_string(r.Y) + "," + std::to_string(r.Width) +
                            "," + std::to_string(r.Height) + ") is outside level " + std::to_string(level) + " (" + std::to_string(w) + "x" +
                            std::to_string(h) + ")");
    checkBlockGrid(r, w, h);
    writeTexels(layer, level, r.X, r.Y, r.Width, r.Height, data, bytes);  // the layer travels as the backend's face
}

void Texture2DArray::getData(int level, int layer, void* data, std::size_t bytes) const {
    throwIfDisposed("GetData");
    checkSubresource("GetData", level, layer);
    if (bytes != layerBytes(level))
        throw ArgumentError(describe() + ": GetData buffer has " + std::to_string(bytes) + " bytes, a layer of level " + std::to_string(level) +
                            " has " + std::to_string(layerBytes(level)));
    readTexels(layer, level, data, bytes);
}

}  // namespace fxport
