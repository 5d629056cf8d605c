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
    d.backend->copySamples(name_, destination.backendObject(), Width(), Height());
}

}  // namespace fxport::core
