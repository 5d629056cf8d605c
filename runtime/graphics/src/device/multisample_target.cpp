#include "device/multisample_target.h"

#include "device/device_impl.h"
#include "fxport/graphics/errors.h"

namespace fxport::core {

// RenderTarget2D makes a single-sample texture; it is replaced at once by the multisampled one, so
// that binding, clears and framebuffers stay RenderTarget2D's own code.
MultisampleTarget::MultisampleTarget(GraphicsDevice& device, int width, int height, SurfaceFormat format, int samples)
    : RenderTarget2D(device, width, height, false, format, DepthFormat::None, 0, fxport::RenderTargetUsage::PreserveContents) {
    GraphicsDevice::Impl& d = deviceImpl(device);
    d.deleteTexture(name_);
    int given = 0;
    name_ = d.createMultisampleTexture(format, samples, width, height, given);
    samples_ = samples;
    if (given != samples)
        throw ArgumentError("a multisampled " + std::string(surfaceFormatName(format)) + " target of " + std::to_string(samples) +
                            " samples: the driver makes " + std::to_string(given) + " (GL_MAX_SAMPLES and the format's limit)");
}

void MultisampleTarget::resolveInto(Texture2D& destination) const {
    if (destination.sampleCount() > 0 || destination.Format() != Format() || destination.Width() != Width() || destination.Height() != Height())
        throw ArgumentError("ResolveSubresource: the destination is not a single-sample " + std::to_string(Width()) + "x" +
                            std::to_string(Height()) + " " + surfaceFormatName(Format()) + " texture");
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.resolvePendingClearBeforeRead(this);
    d.resolvePendingClearBeforeRead(&destination);
    SampleCopy copy;
    copy.source = name_;
    copy.destination = destination.backendObject();
    copy.width = Width();
    copy.height = Height();
    d.backend->copySamples(copy);
}

// As MultisampleTarget: Texture2DArray's single-sample array is replaced at once.
MultisampleArray::MultisampleArray(GraphicsDevice& device, int width, int height, int layers, SurfaceFormat format, int samples)
    : Texture2DArray(device, width, height, layers, 1, format) {
    GraphicsDevice::Impl& d = deviceImpl(device);
    d.deleteTexture(name_);
    int given = 0;
    name_ = d.createMultisampleArrayTexture(format, samples, width, height, layers, given);
    samples_ = samples;
    if (given != samples)
        throw ArgumentError("a multisampled " + std::string(surfaceFormatName(format)) + " array of " + std::to_string(samples) +
                            " samples: the driver makes " + std::to_string(given) + " (GL_MAX_SAMPLES and the format's limit)");
}

void MultisampleArray::resolveLayer(int layer, const Texture& destination, int destinationLayer, int destinationLevel, int width, int height) {
    if (layer < 0 || layer >= Layers())
        throw ArgumentError("ResolveSubresource: layer " + std::to_string(layer) + " of a " + std::to_string(Layers()) + "-layer multisampled array");
    if (destination.sampleCount() > 0 || destination.Format() != Format() || width != Width() || height != Height())
        throw ArgumentError("ResolveSubresource: the destination is not a single-sample " + std::to_string(Width()) + "x" +
                            std::to_string(Height()) + " " + surfaceFormatName(Format()) + " texture");
    GraphicsDevice::Impl& d = deviceImpl(device());
    d.resolvePendingClearBeforeRead(this);
    d.resolvePendingClearBeforeRead(&destination);
    SampleCopy copy;
    copy.source = name_;
    copy.sourceLayer = layer;  // the array's own layer, not a view of it (backend.h)
    copy.destination = destination.backendObject();
    copy.destinationLayer = destinationLayer;
    copy.destinationLevel = destinationLevel;
    copy.width = Width();
    copy.height = Height();
    d.backend->copySamples(copy);
}

void MultisampleArray::resolveInto(int layer, Texture2D& destination) {
    resolveLayer(layer, destination, -1, 0, destination.Width(), destination.Height());
}

void MultisampleArray::resolveInto(int layer, Texture2DArray& destination, int destinationLayer, int destinationLevel) {
    if (destinationLayer < 0 || destinationLayer >= destination.Layers() || destinationLevel < 0 || destinationLevel >= destination.LevelCount())
        throw ArgumentError("ResolveSubresource: layer " + std::to_string(destinationLayer) + ", level " + std::to_string(destinationLevel) +
                            " of the destination array");
    resolveLayer(layer, destination, destinationLayer, destinationLevel, destination.levelWidth(destinationLevel),
                 destination.levelHeight(destinationLevel));
}

}  // namespace fxport::core
