// DeviceQueries and measureDeviceLimits (device_probes.h): the diagnostics' narrow way into a device.
#include "device/device_probes.h"

#include "device/device_impl.h"

namespace fxport {

DeviceQueries::DeviceQueries(GraphicsDevice& device) : device_(deviceImpl(device)) {}

BackendObject DeviceQueries::create(QueryKind kind) { return device_.createQuery(kind); }

void DeviceQueries::remove(BackendObject& query) { device_.deleteQuery(query); }

void DeviceQueries::writeTimestamp(BackendObject query) { device_.backend->writeTimestamp(query); }

void DeviceQueries::beginSamplesPassed(BackendObject query) { device_.backend->beginSamplesPassed(query); }

void DeviceQueries::endSamplesPassed() { device_.backend->endSamplesPassed(); }

bool DeviceQueries::ready(BackendObject query) { return device_.backend->queryReady(query); }

std::uint64_t DeviceQueries::result(BackendObject query) { return device_.backend->queryResult(query); }

bool DeviceQueries::fragmentTallyOn() const { return device_.fragmentTally != nullptr; }

GpuLimits measureDeviceLimits(GraphicsDevice& device, const std::vector<SurfaceFormat>& formats, int size, int repeats) {
    GraphicsDevice::Impl& impl = deviceImpl(device);
    GpuLimits limits = impl.backend->measureLimits(formats, size, repeats);
    // Hand the backend back as the device's shadow says it is; what the shadow cannot say, it re-applies.
    impl.backend->bindSampler(0, impl.boundSamplers[0]);
    impl.backend->bindTexture(0, impl.boundTextures[0]);
    impl.backend->bindVertexArray(impl.boundVertexArray);
    impl.backend->bindPipeline(impl.boundPipeline);
    impl.boundFramebuffer = 0;  // the next draw or clear binds its targets again
    impl.shadow.invalidate();   // and sets every fixed-function state
    return limits;
}

}  // namespace fxport
