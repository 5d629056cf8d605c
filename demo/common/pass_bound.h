// fxport addition (issue 16): each timed pass next to what it writes. While `device` is set, every
// PassTimer records the bytes of the targets the pass bound (each binding once: width x height x
// the format's bytes, + its depth buffer; the back buffer included) -- the bytes the pass writes
// if its draws cover each target's viewport once. With a fill rate (fxdemo --fill-rate GB/s, this
// GPU's fragment output rate, e.g. from a microbenchmark) that is the pass's bound: the time the
// GPU needs just to write those bytes. The timing tables print MB, bound ms and ms / bound.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "fxport/graphics/graphics_device.h"

namespace fxport::demo {

class PassBound {
public:
    static inline GraphicsDevice* device = nullptr;  // set: record (the run's device)
    static inline double fillRateGBps = 0;           // 0: no bound, bytes only

    static void begin();                  // at a pass's start (PassTimer)
    static void end(const std::string& pass);  // at its end: adds the bound targets' bytes
    // Bytes per run of `pass` (the median over its runs, as the times are); 0 when it never ran
    // while recording.
    static double bytesPerRun(const std::string& pass);
    // The timing table's extra columns for `pass` timed at `medianMs`: "  12.3 MB" and, with a fill
    // rate, "  bound 0.216 ms  x5.7"; "" when nothing was recorded.
    static std::string columns(const std::string& pass, double medianMs);

private:
    static inline std::map<std::string, std::vector<double>> writes_;  // bytes of each run
};

}  // namespace fxport::demo
