#include "device/target_view.h"

#include "device/device_impl.h"

namespace fxport::core {

// RenderTarget2D makes a texture of `format` (checking that it is renderable); it is replaced at
// once by the view, as MultisampleTarget replaces its own, so binding and clears stay RenderTarget2D's.
TargetView::TargetView(Texture2D& source, SurfaceFormat format)
    : RenderTarget2D(source.device(), source.Width(), source.Height(), false, format, DepthFormat::None, 0,
                     fxport::RenderTargetUsage::PreserveContents) {
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.deleteTexture(name_);
    name_ = d.createTextureView(describe() + " as " + surfaceFormatName(format), source.backendObject(), format, false, 0, 1, 0, 1);
}

TargetView::TargetView(Texture2DArray& source, int layer, int level, int layers, SurfaceFormat format)
    : RenderTarget2D(source.device(), source.levelWidth(level), source.levelHeight(level), false, format, DepthFormat::None, 0,
                     fxport::RenderTargetUsage::PreserveContents) {
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.deleteTexture(name_);
    name_ = d.createTextureView(describe() + " as " + surfaceFormatName(format), source.backendObject(), format, layers > 1, level, 1, layer, layers);
}

}  // namespace fxport::core
