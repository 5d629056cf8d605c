// The draw hints (draw_hints.h), passed on to the optimisations that use them: the texel-copy
// reduction of compute passes (gl/passes/texel_copies.cpp) and the clear folding
// (device/passes/pending_clear.cpp); each only in a build with it (device/optimization_passes.h).
#include "device/draw_hints.h"

#include "device/compute_passes.h"
#include "device/device_impl.h"
#include "device/optimization_passes.h"

namespace fxport::hints {

const void* boundVertexShader(GraphicsDevice& device) { return deviceImpl(device).shaders[0]; }

bool texelCopiesAvailable(GraphicsDevice& device) { return deviceImpl(device).computePasses != nullptr; }

bool tryTexelCopies(GraphicsDevice& device, const Texture2D& texture, const std::vector<TexelCopy>& copies) {
    GraphicsDevice::Impl& d = deviceImpl(device);
    return d.computePasses && d.computePasses->tryTexelCopies(texture, copies);
}

void nextDrawCoversViewport(GraphicsDevice& device, const void* vertexShader) {
    if constexpr (kPendingClearsBuilt)
        deviceImpl(device).dropColorClearUnderCoveringSprite(static_cast<const ShaderProgram*>(vertexShader));
}

}  // namespace fxport::hints
