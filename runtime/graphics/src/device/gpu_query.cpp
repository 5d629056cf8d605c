// See gpu_query.h.
#include "device/gpu_query.h"

#include "device/device_impl.h"

namespace fxport::core {

GpuQuery::GpuQuery(GraphicsDevice& device, Kind kind) : GraphicsResource(device, "Query"), kind_(kind) {
    name_ = deviceImpl(device).createQuery(kind == Kind::Timestamp ? QueryKind::Timestamp : QueryKind::SamplesPassed);
}

GpuQuery::~GpuQuery() { disposeFromDestructor(); }

void GpuQuery::releaseGpuObjects() {
    BackendObject name = name_;
    deviceImpl(device()).deleteQuery(name);
    name_ = 0;
}

void GpuQuery::begin() {
    throwIfDisposed("begin");
    if (kind_ == Kind::SamplesPassed) deviceImpl(device()).backend->beginSamplesPassed(name_);
}

void GpuQuery::end() {
    throwIfDisposed("end");
    if (kind_ == Kind::SamplesPassed) deviceImpl(device()).backend->endSamplesPassed();
    else deviceImpl(device()).backend->writeTimestamp(name_);
    ended_ = true;
}

bool GpuQuery::ready() {
    throwIfDisposed("ready");
    return ended_ && deviceImpl(device()).backend->queryReady(name_);
}

std::uint64_t GpuQuery::result() {
    throwIfDisposed("result");
    return ended_ ? deviceImpl(device()).backend->queryResult(name_) : 0;
}

}  // namespace fxport::core
