// INTERNAL, GL-free: a GPU query for a front end (D3D11's ID3D11Query): the samples that pass the
// depth and stencil tests between begin() and end(), or the point the GPU has reached at end()
// (its time in nanoseconds; an event query is one whose time nobody reads). Only one samples
// query may count at a time (GL's rule; the front end checks it).
#pragma once

#include <cstdint>

#include "fxport/graphics/graphics_resource.h"

namespace fxport::core {

class GpuQuery : public GraphicsResource {
public:
    enum class Kind { SamplesPassed, Timestamp };
    GpuQuery(GraphicsDevice& device, Kind kind);
    ~GpuQuery() override;
    Kind kind() const { return kind_; }
    void begin();  // SamplesPassed: starts counting (a Timestamp ignores it)
    void end();    // SamplesPassed: stops counting; Timestamp: marks the point
    bool ended() const { return ended_; }
    bool ready();            // the result can be read without waiting (false before the first end())
    std::uint64_t result();  // waits for the GPU; 0 before the first end()

protected:
    void releaseGpuObjects() override;

private:
    Kind kind_;
    std::uint32_t name_ = 0;
    bool ended_ = false;
};

}  // namespace fxport::core
