#include "device/array_format_view.h"

#include "device/device_impl.h"

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

}  // namespace fxport::core
