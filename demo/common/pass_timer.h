// fxport addition to the ported code: times the enclosing block on the GPU under `name` when a
// GpuTimer is attached (fxdemo prints the median per pass); does nothing otherwise.
//
//   { PassTimer timed(gpuTimer, "GBuffer"); MakeGBuffer(GraphicsDevice, Models, Camera); }
//
// A deferring rasterizer (llvmpipe under OSMesa) runs a target's draws when the target is left, so
// its timestamps land in the wrong pass; with syncDevice set, each pass is finished before it
// starts and before it ends, which makes the times attributable (at the cost of pipelining).
//
// With finiteCheck set (fxdemo --check-finite), every target the pass bound is read back when it
// ends (after the timer stops) and scanned for NaN/Inf; the first pass that leaves one throws
// NonFiniteError naming pass, target, pixel and value (common/finite_check.h).
#pragma once

#include <exception>

#include "common/finite_check.h"
#include "common/pass_bound.h"
#include "fxport/graphics/gpu_timer.h"
#include "fxport/graphics/graphics_device.h"

namespace fxport::demo {

class PassTimer {
public:
    PassTimer(GpuTimer* timer, const char* name) : timer_(timer), name_(name) {
        if (finiteCheck) finiteCheck->beginPass(name_);
        PassBound::begin();  // both mark the bound targets at the same point
        if (!timer_) return;
        if (syncDevice) syncDevice->finish();
        timer_->Begin(name);
    }
    // Throws NonFiniteError (only with finiteCheck set, and never while another exception unwinds).
    ~PassTimer() noexcept(false) {
        if (timer_) {
            if (syncDevice) syncDevice->finish();
            timer_->End();
        }
        PassBound::end(name_);
        if (finiteCheck && std::uncaught_exceptions() == 0) throwIfNonFinite(finiteCheck->endPass());
    }
    PassTimer(const PassTimer&) = delete;
    PassTimer& operator=(const PassTimer&) = delete;

    // Set: finish the device around every timed pass (see above).
    static inline GraphicsDevice* syncDevice = nullptr;
    // Set: scan what every pass wrote for NaN/Inf (see above).
    static inline FiniteCheck* finiteCheck = nullptr;

private:
    GpuTimer* timer_;
    const char* name_;
};

}  // namespace fxport::demo
