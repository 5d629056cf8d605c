// See gpu_query.h.
#include "device/gpu_query.h"

#include "device/device_impl.h"
#include "fxport/graphics/errors.h"

namespace fxport::core {

namespace {

static_assert(kPipelineStatistics == 11, "one API query per D3D11_QUERY_DATA_PIPELINE_STATISTICS member");

}  // namespace

bool pipelineStatisticsAvailable(GraphicsDevice& device) { return deviceImpl(device).backend->hasPipelineStatistics(); }

GpuQuery::GpuQuery(GraphicsDevice& device, Kind kind) : GraphicsResource(device, "Query"), kind_(kind) {
    GraphicsDevice::Impl& d = deviceImpl(device);
    if (kind == Kind::PipelineStatistics) {
        if (!d.backend->hasPipelineStatistics())
            throw InvalidOperation("pipeline statistics: the GL driver lacks GL_ARB_pipeline_statistics_query");
        for (int i = 0; i < kPipelineStatistics; ++i) names_[std::size_t(i)] = d.createQuery(pipelineStatistic(i));
        return;
    }
    names_[0] = d.createQuery(kind == Kind::Timestamp ? QueryKind::Timestamp : QueryKind::SamplesPassed);
}

GpuQuery::~GpuQuery() { disposeFromDestructor(); }

void GpuQuery::releaseGpuObjects() {
    for (int i = 0; i < queries(); ++i) {
        BackendObject name = names_[std::size_t(i)];
        deviceImpl(device()).deleteQuery(name);
        names_[std::size_t(i)] = 0;
    }
}

void GpuQuery::begin() {
    throwIfDisposed("begin");
    Backend& backend = *deviceImpl(device()).backend;
    if (kind_ == Kind::SamplesPassed) backend.beginSamplesPassed(names_[0]);
    if (kind_ == Kind::PipelineStatistics)
        for (int i = 0; i < kPipelineStatistics; ++i) backend.beginStatistic(names_[std::size_t(i)], pipelineStatistic(i));
}

void GpuQuery::end() {
    throwIfDisposed("end");
    Backend& backend = *deviceImpl(device()).backend;
    if (kind_ == Kind::SamplesPassed) backend.endSamplesPassed();
    else if (kind_ == Kind::PipelineStatistics)
        for (int i = 0; i < kPipelineStatistics; ++i) backend.endStatistic(pipelineStatistic(i));
    else backend.writeTimestamp(names_[0]);
    ended_ = true;
}

bool GpuQuery::ready() {
    throwIfDisposed("ready");
    if (!ended_) return false;
    Backend& backend = *deviceImpl(device()).backend;
    for (int i = 0; i < queries(); ++i)
        if (!backend.queryReady(names_[std::size_t(i)])) return false;
    return true;
}

std::uint64_t GpuQuery::result() {
    throwIfDisposed("result");
    return ended_ ? deviceImpl(device()).backend->queryResult(names_[0]) : 0;
}

StatisticCounts GpuQuery::statistics() {
    throwIfDisposed("statistics");
    StatisticCounts out{};
    if (!ended_ || kind_ != Kind::PipelineStatistics) return out;
    for (int i = 0; i < kPipelineStatistics; ++i) out[std::size_t(i)] = deviceImpl(device()).backend->queryResult(names_[std::size_t(i)]);
    return out;
}

}  // namespace fxport::core
