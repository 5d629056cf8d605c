// INTERNAL, GL-free: the compute passes (DeviceOptimizations::ComputePasses) as the device core,
// the draw hints and the effects call them. They are GL programs of their own, so they live in the
// backend (gl/passes/compute_pass.h); the core holds one through this interface, null when off.
#pragma once

#include <memory>
#include <vector>

#include "device/backend.h"
#include "device/draw_hints.h"
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
std::shared_ptr<ComputePasses> createComputePasses(GraphicsDevice::Impl& device);

}  // namespace fxport
