// The arithmetic of a pass's bound (issue 16, common/pass_bound.h gathers the inputs): the least
// time the GPU needs for what the pass wrote and fetched, at rates measured once per device
// (fxport::GpuLimits). Two terms, and the bound is the larger:
//   fill  = max(every target the pass wrote, each written once at its format's rate,
//               the clears the pass executed at the clear rate, plus the larger of what its draws
//               wrote once (each target's drawn pixels at its rate) and fragments x the bytes one
//               fragment writes at the pass's fill rate) -- a clear the blend of a later draw
//               reads, XNA's DiscardColor under an alpha-blended frame, is work the pass does, before
//               its draws
//   fetch = the texture fetches of its draws (fragments x the pixel shader's fetches per fragment,
//           summed over runs of draws) at the probe's bilinear fetch rate.
// A fetch count the shader text cannot settle (a branch, a loop of unknown length) enters with its
// least, so the bound stays a bound; fetchesMost and fetchesUnbounded say how far it may be off.
// No GL here: the tests check the arithmetic against hand computations.
#pragma once

#include <string>
#include <vector>

namespace fxport::demo {

struct PassWork {
    struct Target {
        double bytes = 0;     // written once (colour + the depth/stencil buffer if used)
        double rateGBps = 0;  // its format's fill rate (0: unknown, left out)
        double drawnBytes = 0;  // of those, what draws wrote (the rest only clears)
    };
    struct FetchRun {         // draws whose pixel shaders fetch alike (GraphicsDevice::FragmentTally)
        double fragments = 0;
        int least = 0, most = 0;  // fetches per fragment
        bool unbounded = false;
    };
    std::vector<Target> targets;
    double fragments = 0;         // fragments the draws wrote
    int bytesPerFragment = 0;     // the widest colour bytes one fragment wrote
    double fragmentRateGBps = 0;  // what those are written at (0: no fragment term)
    double clearedBytes = 0;      // what the clears the pass executed wrote (each target's widest clear)
    double clearRateGBps = 0;     // the clear rate (0: no clear term)
    std::vector<FetchRun> fetchRuns;
    double fetchRateGTexelsPerSecond = 0;  // 0: no fetch term
};

struct PassEstimate {
    double bytes = 0;         // the targets' bytes, each once
    double fillMs = 0;
    double fetches = 0;       // the least fetches
    double fetchesMost = 0;   // the most, when bounded
    bool fetchesUnbounded = false;
    double fetchMs = 0;       // the least fetches at the fetch rate
    double boundMs() const { return fillMs > fetchMs ? fillMs : fetchMs; }
};

PassEstimate estimate(const PassWork& work);

// Fetches per fragment as the table prints them: "3", "1.4" (runs that differ, averaged over the
// fragments), with "..M" when the most differs and ">=" when unbounded; "-" without fragments.
std::string fetchesPerFragmentText(const PassEstimate& e, double fragments);

}  // namespace fxport::demo
