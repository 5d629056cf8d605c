// fxport addition (issue 16): each timed pass next to what this GPU can do. While `device` is set,
// every PassTimer records the bytes of the targets the pass bound (each binding once: width x
// height x the format's bytes, + its depth buffer; the back buffer included) -- the bytes the pass
// writes if its draws cover each target's viewport once -- and the widest colour bytes one fragment
// wrote and whether it blended. The bound of a pass is the time the GPU needs just to write its
// output: max(those bytes, the fragments the pass wrote (GpuTimer::CountFragments) x bytes per
// fragment) at this GPU's fill rate for the format. The rate comes from `limits` (--bounds: the
// runtime's GpuLimits probe, measured once per device and cached) or from `fillRateGBps`
// (--fill-rate GB/s, one rate for every format). The timing tables print MB, bound ms and
// ms / bound. Texture fetches are not in the bound: a pass far above it that samples a lot is
// fetch-bound (the probe prints the fetch rate to compare with). A pass whose draws ran as compute
// dispatches (PresentationParameters::ComputePasses) writes nothing GL_SAMPLES_PASSED counts: its
// target bytes are bounded at the probe's compute write rate and the table says "compute" instead
// of fragments per pixel.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fxport/graphics/gpu_limits.h"
#include "fxport/graphics/gpu_timer.h"
#include "fxport/graphics/graphics_device.h"

namespace fxport::demo {

class PassBound {
public:
    static inline GraphicsDevice* device = nullptr;  // set: record (the run's device)
    static inline double fillRateGBps = 0;           // --fill-rate; 0: the probe's, or bytes only
    static inline std::optional<GpuLimits> limits;   // --bounds: the measured rates

    // Sets the above from the run's device and options; with `bounds` (--bounds), measures (or
    // loads) the limits, prints them on stdout and has `timer` count fragments.
    static void setUp(GraphicsDevice& runDevice, double fillRate, bool bounds, GpuTimer* timer);

    static void forgetRuns();             // a new measurement (fxdemo report: per setting)
    static void begin();                  // at a pass's start (PassTimer)
    static void end(const std::string& pass);  // at its end: adds the bound targets' bytes
    // Bytes per run of `pass` (the median over its runs, as the times are); 0 when it never ran
    // while recording.
    static double bytesPerRun(const std::string& pass);
    // The bound in ms of `pass` having written `fragments` fragments per run; 0 without a rate.
    static double boundMs(const std::string& pass, double fragments);
    // The timing table's extra columns for a section: "  12.3 MB" and, with a rate,
    // "  bound 0.216 ms  x5.7" (and the fragments per pixel of the targets, when counted);
    // "" when nothing was recorded.
    static std::string columns(const GpuTimer::Section& section);
    static std::string columns(const std::string& pass, double medianMs, double fragments = 0);

private:
    struct Run {
        double bytes = 0;        // the bound targets' bytes, each once
        double writeOnceMs = 0;  // those bytes at the formats' rates (0 without limits)
        int fragmentBytes = 0;   // the widest colour bytes of one fragment
        bool blended = false;
        double rateGBps = 0;     // the fill rate of the widest set's first format
        double pixels = 0;       // the largest bound target's pixels (fragments/px)
        long dispatches = 0;     // draws that ran as compute dispatches
    };
    static inline std::map<std::string, std::vector<Run>> runs_;
    static inline long dispatchedAtBegin_ = 0;
};

}  // namespace fxport::demo
