// INTERNAL, GL-free: the compute passes (DeviceOptimizations::ComputePasses) as the device core,
// the draw hints and the effects call them. They are GL programs of their own, so they live in the
// backend (gl/passes/compute_pass.h); the core holds one through this interface, null when off.
#pragma once

#include <memory>
#include <vector>

#include "device/backend.h"
#include "device/draw_hints.h"
#include "device/pass_emulation.h"
#include "device/shader_program.h"
#include "fxport/graphics/device_statistics.h"
#include "fxport/graphics/graphics_device.h"

namespace fxport {

class Texture2D;
struct ComputeAnalysis;  // what a shader allows, made by the passes (ShaderProgram::computeAnalysis)

class ComputePasses {
public:
    virtual ~ComputePasses() = default;
    // Runs the current draw (flushed, vertex array bound) as a compute dispatch when it may.
    // False: draw it as usual.
    virtual bool tryDraw(PrimitiveType type, int primitiveCount, const DrawCall& draw) = 0;
    // hints::tryTexelCopies: the batch's texel copies as one reduction; false: nothing done.
    virtual bool tryTexelCopies(const Texture2D& texture, const std::vector<TexelCopy>& copies) = 0;
    // Deletes what was made for a shader whose effect releases its programs.
    virtual void forget(const ComputeAnalysis& analysis) = 0;
    // GraphicsDevice::computePassStatistics.
    virtual ComputePassStatistics currentStatistics() = 0;
};

// The GL backend's compute passes over `device` (gl/passes/compute_pass.cpp): their one registration.
std::shared_ptr<ComputePasses> createComputePasses(GraphicsDevice& device);

// What the compute passes read of the device core and ask of it, beside its public state
// (compute_passes.cpp): the draw flush() prepared, and the objects the backend must have back after
// a pass bound its own.
namespace prepared {

// The shader of a draw stage the last applied pass left (null: none).
const ShaderProgram* shader(const GraphicsDevice& device, int stage);
// Work since the last barrier may have written through images or SSBOs.
bool storageWritten(const GraphicsDevice& device);
// The D3D9 states the last applied pass emulates.
const PassEmulation& emulation(const GraphicsDevice& device);
// The bound render targets (empty: the back buffer), the back buffer, and the size of what is bound.
const std::vector<RenderTargetBinding>& targets(const GraphicsDevice& device);
RenderTarget2D* backBuffer(const GraphicsDevice& device);
int targetWidth(const GraphicsDevice& device);
int targetHeight(const GraphicsDevice& device);
// flush's decisions for the draw it prepared: its depth test cannot fail and writes nothing, and
// the blend the draw has (a blend onto a zero clear may be a write).
bool depthTestMoot(const GraphicsDevice& device);
const BlendState& blend(const GraphicsDevice& device);
// The framebuffer and program pipeline the backend has bound for the device.
BackendObject framebuffer(const GraphicsDevice& device);
BackendObject pipeline(const GraphicsDevice& device);
// Everything a draw needs first (GraphicsDevice::Impl::flush); `what` names the call for errors.
void flush(GraphicsDevice& device, const char* what);
// The backend, to issue the draw itself.
Backend& backend(GraphicsDevice& device);

}  // namespace prepared

}  // namespace fxport
