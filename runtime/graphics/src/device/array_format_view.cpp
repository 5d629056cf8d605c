#include "device/array_format_view.h"

#include "device/device_impl.h"
#include "fxport/graphics/errors.h"

namespace fxport::core {

// Texture2DArray's view constructor checks the range and makes a view in the source's format; it
// is replaced at once by one in `format`.
ArrayFormatView::ArrayFormatView(Texture2DArray& source, int firstLevel, int levels, int firstLayer, int layers, SurfaceFormat format)
    : Texture2DArray(source, firstLevel, levels, firstLayer, layers) {
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.deleteTexture(name_);
    name_ = d.createTextureView(describe() + " as " + surfaceFormatName(format), source.backendObject(), format, true, firstLevel, levels, firstLayer,
                                layers);
    format_ = format;
}

ArrayFormatView::ArrayFormatView(Texture2DArray& source, int firstLevel, int levels, Cubes cubes, SurfaceFormat format)
    : Texture2DArray(source, firstLevel, levels, cubes) {
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.deleteTexture(name_);
    name_ = d.backend->createCubeArrayView(source.backendObject(), format, firstLevel, levels, cubes.firstLayer, 6 * cubes.cubes);
    if (name_ == 0) throw InvalidOperation(describe() + ": the graphics API could not make a cube map array view as " + surfaceFormatName(format));
    ++d.live.textures;  // deleted as any texture view is
    format_ = format;
}

}  // namespace fxport::core
