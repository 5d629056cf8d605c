// The device's fragment tally (GraphicsDevice::tallyFragments, for fxdemo --bounds): one
// GL_SAMPLES_PASSED query per run of consecutive draws whose pixel shaders make the same texture
// fetches per fragment, so a pass's fetches are its fragments x each run's fetches.
#pragma once

#include <cstddef>
#include <vector>

#include "fxport/graphics/graphics_device.h"
#include "device/backend.h"
#include "device/device_probes.h"
#include "fxport/xlate/texture_fetches.h"

namespace fxport {

class FragmentRuns {
public:
    explicit FragmentRuns(GraphicsDevice::Impl& device) : device_(device) {}
    ~FragmentRuns();  // ends the open query, deletes every query
    FragmentRuns(const FragmentRuns&) = delete;
    FragmentRuns& operator=(const FragmentRuns&) = delete;

    void beforeDraw(const xlate::TextureFetches& fetches);  // a new run when the fetches change
    std::size_t mark();                                     // ends the open run; collects ready results
    std::vector<GraphicsDevice::FragmentTally> between(std::size_t from, std::size_t to);  // waits

private:
    struct Run {
        xlate::TextureFetches fetches;
        BackendObject query = 0;      // 0 once its result is read
        double fragments = 0;  // the result, once read
    };
    void end();
    void read(Run& run, bool wait);

    DeviceQueries device_;
    std::vector<Run> runs_;
    std::size_t firstUnread_ = 0;  // runs before it have their results
    bool open_ = false;
};

}  // namespace fxport
