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
CubeView::CubeView(Texture2DArray& source, int firstLevel, int levels, int firstLayer)
    : TextureCube(source.device(), checkedSize(source, firstLevel, levels, firstLayer), false, source.Format()) {
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.deleteTexture(name_);
    name_ = d.backend->createCubeView(source.backendObject(), format_, firstLevel, levels, firstLayer);
    if (name_ == 0) throw InvalidOperation(describe() + ": the graphics API could not make a cube map view of an array's layers");
    ++d.live.textures;  // deleted as any texture is
    levels_ = levels;
}

}  // namespace fxport::core
