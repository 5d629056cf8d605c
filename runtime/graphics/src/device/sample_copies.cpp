// Single-sample textures read as Texture2DMS (device_impl.h, sampleCopyOf). D3D lets a shader's
// Texture2DMS.Load(p, 0) read a one-sample texture's texel (vkd3d's suite relies on it); GL's
// sampler2DMS reads only a multisampled texture. The copy is a one-sample multisampled texture,
// rewritten from the source at every draw that binds it so: the source may have changed since.
#include "device/device_impl.h"

namespace fxport {

BackendObject GraphicsDevice::Impl::sampleCopyOf(const Texture& texture) {
    const Rectangle size = backend->textureLevelSize(texture.backendObject(), 0);
    BackendObject& copy = sampleCopies[&texture];
    if (!copy) {
        int given = 0;
        copy = createMultisampleTexture(texture.Format(), 1, size.Width, size.Height, given);
    }
    resolvePendingClearBeforeRead(&texture);
    SampleCopy samples;
    samples.source = texture.backendObject();
    samples.destination = copy;
    samples.width = size.Width;
    samples.height = size.Height;
    backend->copySamples(samples);
    return copy;
}

void GraphicsDevice::Impl::forgetSampleCopy(const Texture* texture) {
    auto it = sampleCopies.find(texture);
    if (it == sampleCopies.end()) return;
    deleteTexture(it->second);
    sampleCopies.erase(it);
}

}  // namespace fxport
