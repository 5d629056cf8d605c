// estimate(): a pass's fill and fetch terms from the bytes, fragments and fetches it was measured with.
#include "common/pass_estimate.h"

#include <algorithm>
#include <cstdio>

namespace fxport::demo {

namespace {
double msAt(double amount, double ratePerSecond) { return ratePerSecond > 0 ? amount / ratePerSecond * 1e3 : 0; }
}  // namespace

PassEstimate estimate(const PassWork& work) {
    PassEstimate e;
    double writeOnceMs = 0, drawnOnceMs = 0;
    for (const PassWork::Target& t : work.targets) {
        e.bytes += t.bytes;
        writeOnceMs += msAt(t.bytes, t.rateGBps * 1e9);
        drawnOnceMs += msAt(t.drawnBytes, t.rateGBps * 1e9);
    }
    // Clears and draws write the same memory one after the other: their times add.
    const double drawMs = std::max(drawnOnceMs, msAt(work.fragments * work.bytesPerFragment, work.fragmentRateGBps * 1e9));
    e.fillMs = std::max(writeOnceMs, msAt(work.clearedBytes, work.clearRateGBps * 1e9) + drawMs);
    for (const PassWork::FetchRun& run : work.fetchRuns) {
        e.fetches += run.fragments * run.least;
        e.fetchesMost += run.fragments * run.most;
        e.fetchesUnbounded = e.fetchesUnbounded || run.unbounded;
    }
    e.fetchMs = msAt(e.fetches, work.fetchRateGTexelsPerSecond * 1e9);
    return e;
}

std::string fetchesPerFragmentText(const PassEstimate& e, double fragments) {
    if (!(fragments > 0)) return "-";
    char text[64];
    auto number = [](double v, char* out, std::size_t size) {
        // Whole numbers as such (the common case: one shader), else one decimal.
        if (v == double(long(v))) std::snprintf(out, size, "%ld", long(v));
        else std::snprintf(out, size, "%.1f", v);
    };
    char least[24], most[24];
    number(e.fetches / fragments, least, sizeof least);
    number(e.fetchesMost / fragments, most, sizeof most);
    if (e.fetchesUnbounded) std::snprintf(text, sizeof text, ">=%s", least);
    else if (e.fetchesMost > e.fetches) std::snprintf(text, sizeof text, "%s..%s", least, most);
    else std::snprintf(text, sizeof text, "%s", least);
    return text;
}

}  // namespace fxport::demo
