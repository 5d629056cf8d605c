// What the compute passes read of the device core (compute_passes.h, namespace prepared), over its
// private state.
#include "device/compute_passes.h"

#include "device/device_impl.h"

namespace fxport::prepared {

const ShaderProgram* shader(const GraphicsDevice& device, int stage) { return deviceImpl(device).shaders[std::size_t(stage)]; }
bool storageWritten(const GraphicsDevice& device) { return deviceImpl(device).storageDirty; }
const PassEmulation& emulation(const GraphicsDevice& device) { return deviceImpl(device).emulation; }
const std::vector<RenderTargetBinding>& targets(const GraphicsDevice& device) { return deviceImpl(device).targets; }
RenderTarget2D* backBuffer(const GraphicsDevice& device) { return deviceImpl(device).backBuffer.get(); }
int targetWidth(const GraphicsDevice& device) { return deviceImpl(device).targetWidth; }
int targetHeight(const GraphicsDevice& device) { return deviceImpl(device).targetHeight; }
bool depthTestMoot(const GraphicsDevice& device) { return deviceImpl(device).drawDepthTestMoot; }
const BlendState& blend(const GraphicsDevice& device) { return deviceImpl(device).drawBlend(); }
BackendObject framebuffer(const GraphicsDevice& device) { return deviceImpl(device).boundFramebuffer; }
BackendObject pipeline(const GraphicsDevice& device) { return deviceImpl(device).boundPipeline; }
void flush(GraphicsDevice& device, const char* what) { deviceImpl(device).flush(what); }
Backend& backend(GraphicsDevice& device) { return *deviceImpl(device).backend; }

}  // namespace fxport::prepared
