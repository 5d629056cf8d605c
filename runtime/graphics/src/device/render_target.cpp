#include "fxport/graphics/render_target.h"

#include <algorithm>

#include "device/device_impl.h"
#include "fxport/graphics/errors.h"

namespace fxport {

namespace {

void checkRenderable(GraphicsDevice& device, const std::string& who, SurfaceFormat format) {
    if (!deviceImpl(device).backend->isColorRenderable(format))
        throw ArgumentError(who + ": SurfaceFormat::" + surfaceFormatName(format) +
                            " cannot be rendered to on OpenGL 4.5 core");
}

// The depth/stencil buffer is made now, or at the first draw that needs it (depth_storage.cpp).
void adoptDepth(GraphicsDevice& device, DepthStorage& storage, DepthFormat format, int width, int height) {
    storage.format = format;
    storage.width = width;
    storage.height = height;
    deviceImpl(device).adoptDepthStorage(storage);
}

// Unbinds the target from the device's current render targets (back to the back buffer) when it
// is destroyed while bound.
void unbindIfTarget(GraphicsDevice& device, const Texture* target) {
    auto& noted = deviceImpl(device).boundSinceMark;
    noted.erase(std::remove_if(noted.begin(), noted.end(), [&](const RenderTargetBinding& b) { return b.RenderTarget == target; }),
                noted.end());
    std::erase_if(deviceImpl(device).writtenSinceMark,
                  [&](const GraphicsDevice::WrittenTarget& w) { return w.binding.RenderTarget == target; });
    auto& targets = deviceImpl(device).targets;
    bool bound = std::any_of(targets.begin(), targets.end(),
                             [&](const RenderTargetBinding& b) { return b.RenderTarget == target; });
    if (bound) device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
}

}  // namespace

RenderTarget2D::RenderTarget2D(fxport::GraphicsDevice& device, int width, int height, bool mipMap,
                               SurfaceFormat preferredFormat, DepthFormat preferredDepthFormat, int,
                               fxport::RenderTargetUsage usage)
    : Texture2D(device, "RenderTarget2D", width, height, mipMap, preferredFormat),
      usage_(usage) {
    checkRenderable(device, describe(), preferredFormat);
    adoptDepth(device, depth_, preferredDepthFormat, width, height);
}

RenderTarget2D::RenderTarget2D(Texture2DArray& array, int layer, int level, int layers)
    : Texture2D(array.device(), "RenderTarget2D", array.levelWidth(level), array.levelHeight(level), array.Format(),
                array.layerView("a RenderTarget2D over layers", layer, level, layers)),
      usage_(fxport::RenderTargetUsage::PreserveContents) {
    samples_ = array.sampleCount();  // layers of a multisampled array (core::MultisampleArray)
    checkRenderable(device(), describe(), Format());
    adoptDepth(device(), depth_, DepthFormat::None, Width(), Height());
}

RenderTarget2D::RenderTarget2D(fxport::GraphicsDevice& device, int width, SurfaceFormat format, std::uint32_t row)
    : Texture2D(device, "RenderTarget2D", width, 1, format, row), usage_(fxport::RenderTargetUsage::PreserveContents) {
    checkRenderable(this->device(), describe(), Format());
    adoptDepth(this->device(), depth_, DepthFormat::None, Width(), Height());
}

RenderTarget2D::~RenderTarget2D() { disposeFromDestructor(); }

void RenderTarget2D::releaseGpuObjects() {
    unbindIfTarget(device(), this);
    deviceImpl(device()).releaseDepthStorage(depth_);
    Texture2D::releaseGpuObjects();
}

std::vector<Vector4> RenderTarget2D::GetDataAsVector4() const {
    throwIfDisposed("GetDataAsVector4");
    std::vector<Vector4> texels(std::size_t(Width()) * std::size_t(Height()));
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.resolvePendingClearBeforeRead(this);
    d.backend->readTextureFloats(name_, -1, 0, texels.size() * sizeof(Vector4), texels.data());
    return texels;
}

RenderTargetCube::RenderTargetCube(fxport::GraphicsDevice& device, int size, bool mipMap,
                                   SurfaceFormat preferredFormat, DepthFormat preferredDepthFormat, int,
                                   fxport::RenderTargetUsage usage)
    : TextureCube(device, "RenderTargetCube", size, mipMap, preferredFormat),
      usage_(usage) {
    checkRenderable(device, describe(), preferredFormat);
    adoptDepth(device, depth_, preferredDepthFormat, size, size);
}

RenderTargetCube::~RenderTargetCube() { disposeFromDestructor(); }

void RenderTargetCube::releaseGpuObjects() {
    unbindIfTarget(device(), this);
    deviceImpl(device()).releaseDepthStorage(depth_);
    TextureCube::releaseGpuObjects();
}

std::vector<Vector4> RenderTargetCube::GetDataAsVector4(CubeMapFace face) const {
    throwIfDisposed("GetDataAsVector4");
    std::vector<Vector4> texels(std::size_t(Size()) * std::size_t(Size()));
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.resolvePendingClearBeforeRead(this);
    d.backend->readTextureFloats(name_, int(face), 0, texels.size() * sizeof(Vector4), texels.data());
    return texels;
}

}  // namespace fxport
