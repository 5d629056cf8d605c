// fxport addition (issue 16): each timed pass next to what this GPU can do. While `device` is set,
// every PassTimer records what the pass wrote and fetched, and the timing tables print
//   MB          the targets the pass wrote (draws or clears; a target only bound is not counted),
//               each once: the pixels its widest clear or draw covered x the format's bytes, + its
//               depth/stencil buffer's where a draw tested it or a clear wrote it (a buffer lazy
//               depth storage never made has none). A draw covers at most its viewport (within the
//               scissor) and, with fragments counted, at most the pass's fragments: a sprite in a
//               corner of the back buffer does not count the whole of it
//   fill ms     max(those bytes, fragments x the widest colour bytes one fragment wrote) at this
//               GPU's fill rate for the format (opaque, or additive when a draw blended)
//   fetch ms    the texture fetches the draws made at the probe's bilinear fetch rate (--bounds)
//   bound ms    the larger of the two; then x(ms / bound), fragments per pixel and fetches per
//               fragment (common/pass_estimate.h has the arithmetic)
// Fragments and fetches come from the device's fragment tally (GraphicsDevice::tallyFragments:
// GL_SAMPLES_PASSED per run of draws whose pixel shaders make the same fetches per fragment, the
// fetches counted in the shader's GLSL by xlate::countTextureFetches). The rates come from `limits`
// (--bounds: the runtime's GpuLimits probe, measured once per device and cached) or from
// `fillRateGBps` (--fill-rate GB/s, one rate for every format; no fragments or fetches then).
// A pass whose draws ran as compute dispatches (DeviceOptimizations::ComputePasses) writes no
// fragments GL_SAMPLES_PASSED counts: its target bytes are bounded at the probe's compute write rate
// and the table says "compute" instead of fragments per pixel.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "common/pass_estimate.h"
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
    // loads) the limits, prints them on stdout and has the device tally fragments and fetches.
    static void setUp(GraphicsDevice& runDevice, double fillRate, bool bounds);
    // Has the device tally fragments by fetches from now on (what setUp does with --bounds).
    static void tallyOn(GraphicsDevice& runDevice);

    static void forgetRuns();             // a new measurement (fxdemo report: per setting)
    static void begin();                  // at a pass's start (PassTimer)
    static void end(const std::string& pass);  // at its end: what the pass wrote
    // The pass's estimate (the median run's, by bound), its fragments and pixels; nullopt when it
    // never ran while recording. Reading the fragment tally waits for the GPU.
    struct Summary {
        PassEstimate estimate;
        double fragments = 0;  // per run
        double pixels = 0;     // the largest written target's
        long dispatches = 0;   // draws that ran as compute dispatches
    };
    static std::optional<Summary> summary(const std::string& pass);
    static double bytesPerRun(const std::string& pass);
    static double boundMs(const std::string& pass);  // 0 without a rate
    // The timing table's extra columns for a section (see the top); "" when nothing was recorded.
    static std::string columns(const GpuTimer::Section& section);
    static std::string columns(const std::string& pass, double medianMs);

private:
    struct Written {                   // a target the pass wrote (GraphicsDevice::WrittenTarget)
        double drawnPixels = 0, clearedPixels = 0, colorClearedPixels = 0;
        double bytesPerPixel = 0;      // colour and depth/stencil as written
        double colorBytesPerPixel = 0; // colour alone (what a colour clear writes)
        double rateGBps = 0;
    };
    struct Run {
        PassWork work;                 // targets, fragments and fetches filled in when the tally is read
        std::vector<Written> written;
        bool counted = false;          // fragments were counted (the tally was on)
        std::size_t tallyFrom = 0, tallyTo = 0;
        bool tallied = false;          // the tally's runs were read into `work`
        double pixels = 0;
        long dispatches = 0;
    };
    static void readTally(Run& run);
    static inline std::map<std::string, std::vector<Run>> runs_;
    static inline long dispatchedAtBegin_ = 0;
    static inline GraphicsDevice* tallyDevice_ = nullptr;  // the device whose tally the runs index
    static inline std::vector<std::size_t> openTallyMarks_;  // per open pass (passes nest)
};

}  // namespace fxport::demo
