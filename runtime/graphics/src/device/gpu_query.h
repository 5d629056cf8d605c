// INTERNAL, GL-free: a GPU query for a front end (D3D11's ID3D11Query): the samples that pass the
// depth and stencil tests between begin() and end(), the point the GPU has reached at end() (its
// time in nanoseconds; an event query is one whose time nobody reads), or the pipeline statistics
// counted between begin() and end() (D3D11_QUERY_PIPELINE_STATISTICS: one API query per counter,
// where the API has them -- pipelineStatisticsAvailable). Only one samples query, and one
// statistics query, may count at a time (GL's rule; the front end checks it).
#pragma once

#include <array>
#include <cstdint>

#include "fxport/graphics/graphics_resource.h"

namespace fxport::core {

// The counters of a PipelineStatistics query, in D3D11_QUERY_DATA_PIPELINE_STATISTICS's order.
using StatisticCounts = std::array<std::uint64_t, 11>;
bool pipelineStatisticsAvailable(GraphicsDevice& device);

class GpuQuery : public GraphicsResource {
public:
    enum class Kind { SamplesPassed, Timestamp, PipelineStatistics };
    // Throws InvalidOperation for PipelineStatistics where !pipelineStatisticsAvailable.
    GpuQuery(GraphicsDevice& device, Kind kind);
    ~GpuQuery() override;
    Kind kind() const { return kind_; }
    void begin();  // SamplesPassed, PipelineStatistics: starts counting (a Timestamp ignores it)
    void end();    // SamplesPassed, PipelineStatistics: stops counting; Timestamp: marks the point
    bool ended() const { return ended_; }
    bool ready();            // the result can be read without waiting (false before the first end())
    std::uint64_t result();  // waits for the GPU; 0 before the first end() (PipelineStatistics: IAVertices)
    StatisticCounts statistics();  // waits; zeros before the first end() or for another kind

protected:
    void releaseGpuObjects() override;

private:
    Kind kind_;
    std::array<std::uint32_t, 11> names_{};  // [0] only, but for PipelineStatistics
    bool ended_ = false;
    int queries() const { return kind_ == Kind::PipelineStatistics ? int(names_.size()) : 1; }
};

}  // namespace fxport::core
