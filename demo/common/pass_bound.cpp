// PassBound: the bytes of the targets each pass bound, from GraphicsDevice::targetsBoundSinceMark,
// against the fill rate of GpuLimits (or --fill-rate).
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
}  // namespace

void PassBound::setUp(GraphicsDevice& runDevice, double fillRate, bool bounds, GpuTimer* timer) {
    device = &runDevice;
    fillRateGBps = fillRate;
    limits.reset();
    if (!bounds) return;
    limits = GpuLimits::ForDevice(runDevice);
    if (timer) timer->CountFragments(true);
    std::printf("GPU limits of %s (measured once, cached):\n  fill GB/s (opaque / additive):", limits->renderer.c_str());
    for (const GpuLimits::Fill& f : limits->fill)
        std::printf(" %s %.1f/%.1f", surfaceFormatName(f.format), f.opaqueGBps, f.blendedGBps);
    std::printf("\n  clear %.1f GB/s, bilinear fetch %.1f Gtexel/s, compute image write %.1f GB/s\n", limits->clearGBps,
                limits->fetchGTexelsPerSecond, limits->computeWriteGBps);
}

void PassBound::forgetRuns() { runs_.clear(); }

void PassBound::begin() {
    if (!device) return;
    device->markBoundTargets();
    dispatchedAtBegin_ = device->computePassStatistics().issued;  // counted at once (dispatched waits for the GPU)
}

void PassBound::end(const std::string& pass) {
    if (!device) return;
    Run run;
    run.blended = device->blendedSinceMark();
    run.fragmentBytes = device->colorBytesPerFragmentSinceMark();
    run.dispatches = device->computePassStatistics().issued - dispatchedAtBegin_;
    auto rate = [&](SurfaceFormat format) {
        if (run.dispatches > 0 && limits && limits->computeWriteGBps > 0) return limits->computeWriteGBps;
        return limits ? limits->fillGBps(format, run.blended) : fillRateGBps;
    };
    for (const RenderTargetBinding& binding : device->targetsBoundSinceMark()) {
        double bytes = 0, pixels = 0;
        SurfaceFormat format = SurfaceFormat::Color;
        if (const auto* target = dynamic_cast<const RenderTarget2D*>(binding.RenderTarget)) {
            bytes = double(RenderTargetBytes(target->Width(), target->Height(), 1, target->Format(), target->DepthStencilFormat()));
            pixels = double(target->Width()) * target->Height();
            format = target->Format();
        } else if (const auto* cube = dynamic_cast<const RenderTargetCube*>(binding.RenderTarget)) {
            bytes = double(RenderTargetBytes(cube->Size(), cube->Size(), 1, cube->Format(), cube->DepthStencilFormat()));
            pixels = double(cube->Size()) * cube->Size();
            format = cube->Format();
        }
        if (run.rateGBps == 0) run.rateGBps = rate(format);
        run.bytes += bytes;
        run.pixels = std::max(run.pixels, pixels);
        if (rate(format) > 0) run.writeOnceMs += bytes / (rate(format) * 1e9) * 1e3;
    }
    runs_[pass].push_back(run);
}

double PassBound::bytesPerRun(const std::string& pass) {
    auto found = runs_.find(pass);
    if (found == runs_.end() || found->second.empty()) return 0.0;
    std::vector<double> bytes;
    for (const Run& r : found->second) bytes.push_back(r.bytes);
    return median(bytes);
}

double PassBound::boundMs(const std::string& pass, double fragments) {
    auto found = runs_.find(pass);
    if (found == runs_.end() || found->second.empty()) return 0.0;
    std::vector<double> bounds;
    for (const Run& r : found->second) {
        const double fragmentMs = r.rateGBps > 0 ? fragments * r.fragmentBytes / (r.rateGBps * 1e9) * 1e3 : 0;
        bounds.push_back(std::max(r.writeOnceMs, fragmentMs));
    }
    return median(bounds);
}

std::string PassBound::columns(const GpuTimer::Section& section) {
    return columns(section.name, section.medianMs(), section.medianFragments());
}

std::string PassBound::columns(const std::string& pass, double medianMs, double fragments) {
    auto found = runs_.find(pass);
    if (found == runs_.end()) return {};
    const double bytes = bytesPerRun(pass);
    const double bound = boundMs(pass, fragments);
    char text[192];
    int n = std::snprintf(text, sizeof text, "  %9.2f MB", bytes / 1e6);
    if (bound > 0)
        n += std::snprintf(text + n, sizeof text - std::size_t(n), "  bound %8.3f ms  x%.1f", bound, medianMs / bound);
    std::vector<double> pixels;
    long dispatches = 0;
    for (const Run& r : found->second) pixels.push_back(r.pixels), dispatches = std::max(dispatches, r.dispatches);
    if (dispatches > 0)
        std::snprintf(text + n, sizeof text - std::size_t(n), "  compute (%ld dispatches)", dispatches);
    else if (fragments > 0 && median(pixels) > 0)
        std::snprintf(text + n, sizeof text - std::size_t(n), "  %.2f fragments/px", fragments / median(pixels));
    return text;
}

}  // namespace fxport::demo
