// fxport addition to the ported code: times the enclosing block on the GPU under `name` when a
// GpuTimer is attached (fxdemo prints the median per pass); does nothing otherwise.
//
//   { PassTimer timed(gpuTimer, "GBuffer"); MakeGBuffer(GraphicsDevice, Models, Camera); }
//
// A deferring rasterizer (llvmpipe under OSMesa) runs a target's draws when the target is left, so
// its timestamps land in the wrong pass; with syncDevice set, each pass is finished before it
// starts and before it ends, which makes the times attributable (at the cost of pipelining).
#pragma once

#include "fxport/graphics/gpu_timer.h"
#include "fxport/graphics/graphics_device.h"

namespace fxport::demo {

class PassTimer {
public:
    PassTimer(GpuTimer* timer, const char* name) : timer_(timer) {
        if (!timer_) return;
        if (syncDevice) syncDevice->finish();
        timer_->Begin(name);
    }
    ~PassTimer() {
        if (!timer_) return;
        if (syncDevice) syncDevice->finish();
        timer_->End();
    }
    PassTimer(const PassTimer&) = delete;
    PassTimer& operator=(const PassTimer&) = delete;

    // Set: finish the device around every timed pass (see above).
    static inline GraphicsDevice* syncDevice = nullptr;

private:
    GpuTimer* timer_;
};

}  // namespace fxport::demo
