// INTERNAL, GL-free: what the diagnostics (diagnostics/: GpuTimer, the fragment tally, GpuLimits)
// may ask of a device, so they need not see its private state (device/device_impl.h): queries made
// and deleted through the device's bookkeeping (liveGpuObjects() stays exact), the backend's query
// calls, and a limits measurement that hands the backend back as the device's shadow has it.
#pragma once

#include <cstdint>
#include <vector>

#include "device/backend.h"
#include "fxport/graphics/graphics_device.h"
#include "fxport/graphics/gpu_limits.h"

namespace fxport {

class DeviceQueries {
public:
    explicit DeviceQueries(GraphicsDevice& device);
    explicit DeviceQueries(GraphicsDevice::Impl& device) : device_(device) {}

    BackendObject create(QueryKind kind);
    void remove(BackendObject& query);  // deletes it and sets it to 0
    void writeTimestamp(BackendObject query);
    void beginSamplesPassed(BackendObject query);
    void endSamplesPassed();
    bool ready(BackendObject query);
    std::uint64_t result(BackendObject query);  // waits
    bool fragmentTallyOn() const;  // GraphicsDevice::tallyFragments(true): it owns the samples query

private:
    GraphicsDevice::Impl& device_;
};

// The backend's measurement (Backend::measureLimits), then the backend's bindings restored from the
// device's shadow and every fixed-function state marked for re-applying.
GpuLimits measureDeviceLimits(GraphicsDevice& device, const std::vector<SurfaceFormat>& formats, int size, int repeats);

}  // namespace fxport
