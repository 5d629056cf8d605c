#include "device/cube_view.h"

#include "device/device_impl.h"
#include "fxport/graphics/errors.h"

namespace fxport::core {

namespace {

int checkedSize(const Texture2DArray& source, int firstLevel, int levels, int firstLayer) {
    if (firstLevel < 0 || levels <= 0 || firstLevel + levels > source.LevelCount() || firstLayer < 0 || firstLayer + 6 > source.Layers() ||
        source.Width() != source.Height())
        throw ArgumentError("a cube of layers " + std::to_string(firstLayer) + "-" + std::to_string(firstLayer + 5) + ", levels " +
                            std::to_string(firstLevel) + "+" + std::to_string(levels) + " of a " + std::to_string(source.Width()) + "x" +
                            std::to_string(source.Height()) + " array of " + std::to_string(source.Layers()) + " layers and " +
                            std::to_string(source.LevelCount()) + " levels (cubes are square)");
    return source.levelWidth(firstLevel);
}

}  // namespace

// TextureCube makes a cube of one level; it is replaced at once by the view of the array's faces.
CubeView::CubeView(Texture2DArray& source, int firstLevel, int levels, int firstLayer, SurfaceFormat format)
    : TextureCube(source.device(), checkedSize(source, firstLevel, levels, firstLayer), false, format) {
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.deleteTexture(name_);
    name_ = d.backend->createCubeView(source.backendObject(), format_, firstLevel, levels, firstLayer);
    if (name_ == 0) throw InvalidOperation(describe() + ": the graphics API could not make a cube map view of an array's layers");
    ++d.live.textures;  // deleted as any texture is
    levels_ = levels;
}

// GL views a cube map as a cube map the same way (its six faces are its layers).
CubeView::CubeView(TextureCube& source, SurfaceFormat format) : TextureCube(source.device(), source.Size(), false, format) {
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.deleteTexture(name_);
    name_ = d.backend->createCubeView(source.backendObject(), format_, 0, source.LevelCount(), 0);
    if (name_ == 0) throw InvalidOperation(describe() + ": the graphics API could not view a cube as " + std::string(surfaceFormatName(format)));
    ++d.live.textures;
    levels_ = source.LevelCount();
}

}  // namespace fxport::core
