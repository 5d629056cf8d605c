// PassBound: what each pass wrote (GraphicsDevice::targetsWrittenSinceMark) and fetched (the
// device's fragment tally), against the rates of GpuLimits (or --fill-rate).
#include "common/pass_bound.h"

#include <algorithm>
#include <cstdio>

#include "common/build_report.h"

namespace fxport::demo {

namespace {
template <class T>
T median(std::vector<T> v) {
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : (v[n / 2 - 1] + v[n / 2]) / 2;
}

double depthBytes(int width, int height, SurfaceFormat format, DepthFormat depth) {
    return double(RenderTargetBytes(width, height, 1, format, depth)) -
           double(RenderTargetBytes(width, height, 1, format, DepthFormat::None));
}
}  // namespace

void PassBound::setUp(GraphicsDevice& runDevice, double fillRate, bool bounds) {
    device = &runDevice;
    fillRateGBps = fillRate;
    limits.reset();
    tallyDevice_ = nullptr;
    if (!bounds) return;
    limits = GpuLimits::ForDevice(runDevice);
    tallyOn(runDevice);
    std::printf("GPU limits of %s (measured once, cached):\n  fill GB/s (opaque / additive):", limits->renderer.c_str());
    for (const GpuLimits::Fill& f : limits->fill)
        std::printf(" %s %.1f/%.1f", surfaceFormatName(f.format), f.opaqueGBps, f.blendedGBps);
    std::printf("\n  clear %.1f GB/s, bilinear fetch %.1f Gtexel/s, compute image write %.1f GB/s\n", limits->clearGBps,
                limits->fetchGTexelsPerSecond, limits->computeWriteGBps);
}

void PassBound::tallyOn(GraphicsDevice& runDevice) {
    runDevice.tallyFragments(true);
    tallyDevice_ = &runDevice;
}

void PassBound::forgetRuns() {
    runs_.clear();
    openTallyMarks_.clear();
}

void PassBound::begin() {
    if (!device) return;
    device->markBoundTargets();
    dispatchedAtBegin_ = device->computePassStatistics().issued;  // counted at once (dispatched waits for the GPU)
    if (tallyDevice_ == device) openTallyMarks_.push_back(device->fragmentTallyMark());
}

void PassBound::end(const std::string& pass) {
    if (!device) return;
    Run run;
    PassWork& work = run.work;
    const bool blended = device->blendedSinceMark();
    work.bytesPerFragment = device->colorBytesPerFragmentSinceMark();
    run.dispatches = device->computePassStatistics().issued - dispatchedAtBegin_;
    auto rate = [&](SurfaceFormat format) {
        if (run.dispatches > 0 && limits && limits->computeWriteGBps > 0) return limits->computeWriteGBps;
        return limits ? limits->fillGBps(format, blended) : fillRateGBps;
    };
    for (const GraphicsDevice::WrittenTarget& written : device->targetsWrittenSinceMark()) {
        int width = 0, height = 0;
        SurfaceFormat format = SurfaceFormat::Color;
        DepthFormat depth = DepthFormat::None;
        if (const auto* target = dynamic_cast<const RenderTarget2D*>(written.binding.RenderTarget)) {
            width = target->Width(), height = target->Height();
            format = target->Format(), depth = target->DepthStencilFormat();
        } else if (const auto* cube = dynamic_cast<const RenderTargetCube*>(written.binding.RenderTarget)) {
            width = height = cube->Size();
            format = cube->Format(), depth = cube->DepthStencilFormat();
        }
        const double pixels = double(width) * height;
        double bytes = 0;  // the whole target's
        if (written.color) bytes += double(RenderTargetBytes(width, height, 1, format, DepthFormat::None));
        if (written.depthStencil) bytes += depthBytes(width, height, format, depth);
        // The pass's fragments are written at the rate of the first target it wrote.
        if (work.fragmentRateGBps == 0) work.fragmentRateGBps = rate(format);
        const double colorBytes = double(RenderTargetBytes(width, height, 1, format, DepthFormat::None));
        run.written.push_back({written.drawnPixels, written.clearedPixels, written.colorClearedPixels, pixels > 0 ? bytes / pixels : 0,
                               pixels > 0 ? colorBytes / pixels : 0, rate(format)});
        run.pixels = std::max(run.pixels, pixels);
    }
    if (limits) work.fetchRateGTexelsPerSecond = limits->fetchGTexelsPerSecond, work.clearRateGBps = limits->clearGBps;
    if (tallyDevice_ == device && !openTallyMarks_.empty()) {
        run.tallyFrom = openTallyMarks_.back();
        openTallyMarks_.pop_back();
        run.tallyTo = device->fragmentTallyMark();
        run.counted = true;
    }
    runs_[pass].push_back(run);
}

void PassBound::readTally(Run& run) {
    if (run.tallied) return;
    run.tallied = true;
    if (run.counted && tallyDevice_)
        for (const GraphicsDevice::FragmentTally& t : tallyDevice_->fragmentTallies(run.tallyFrom, run.tallyTo)) {
            run.work.fragments += t.fragments;
            run.work.fetchRuns.push_back({t.fragments, t.fetchesLeast, t.fetchesMost, t.fetchesUnbounded});
        }
    // Each target once: what its widest clear covered, or its widest draw's viewport -- which a
    // draw's fragments bound when they were counted (a pixel written needs a fragment that passed).
    // Compute dispatches write pixels without fragments. Only colour clears enter the clear term:
    // depth/stencil clears are fast clears (the deferred composition's depth clear is no 4 B/px
    // of traffic), and the term must stay a bound.
    for (const Written& w : run.written) {
        const double drawn = run.counted && run.dispatches == 0 ? std::min(w.drawnPixels, run.work.fragments) : w.drawnPixels;
        run.work.targets.push_back({std::max(drawn, w.clearedPixels) * w.bytesPerPixel, w.rateGBps, drawn * w.bytesPerPixel});
        run.work.clearedBytes += w.colorClearedPixels * w.colorBytesPerPixel;
    }
}

std::optional<PassBound::Summary> PassBound::summary(const std::string& pass) {
    auto found = runs_.find(pass);
    if (found == runs_.end() || found->second.empty()) return std::nullopt;
    std::vector<std::pair<double, std::size_t>> byBound;  // the run whose bound is the median
    for (std::size_t i = 0; i < found->second.size(); ++i) {
        Run& run = found->second[i];
        readTally(run);
        byBound.emplace_back(estimate(run.work).boundMs(), i);
    }
    std::sort(byBound.begin(), byBound.end());
    const Run& middle = found->second[byBound[(byBound.size() - 1) / 2].second];
    Summary s;
    s.estimate = estimate(middle.work);
    s.fragments = middle.work.fragments;
    s.pixels = middle.pixels;
    for (const Run& r : found->second) s.dispatches = std::max(s.dispatches, r.dispatches);
    return s;
}

double PassBound::bytesPerRun(const std::string& pass) {
    auto found = runs_.find(pass);
    if (found == runs_.end() || found->second.empty()) return 0.0;
    std::vector<double> bytes;
    for (Run& r : found->second) {
        readTally(r);
        bytes.push_back(estimate(r.work).bytes);
    }
    return median(bytes);
}

double PassBound::boundMs(const std::string& pass) {
    const std::optional<Summary> s = summary(pass);
    return s ? s->estimate.boundMs() : 0.0;
}

std::string PassBound::columns(const GpuTimer::Section& section) { return columns(section.name, section.medianMs()); }

std::string PassBound::columns(const std::string& pass, double medianMs) {
    const std::optional<Summary> s = summary(pass);
    if (!s) return {};
    const PassEstimate& e = s->estimate;
    char text[256];
    int n = std::snprintf(text, sizeof text, "  %9.2f MB", e.bytes / 1e6);
    auto add = [&](const char* format, auto... values) {
        n += std::snprintf(text + n, sizeof text - std::size_t(n), format, values...);
    };
    if (e.boundMs() > 0) {
        add("  fill %8.3f ms", e.fillMs);
        if (limits) add("  fetch %8.3f ms", e.fetchMs);
        add("  bound %8.3f ms  x%-5.1f", e.boundMs(), medianMs / e.boundMs());
    }
    if (s->dispatches > 0) add("  compute (%ld dispatches)", s->dispatches);
    else if (s->fragments > 0 && s->pixels > 0)
        add("  %6.2f fragments/px  %s fetches/fragment", s->fragments / s->pixels, fetchesPerFragmentText(e, s->fragments).c_str());
    return text;
}

}  // namespace fxport::demo
