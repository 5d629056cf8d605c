// PassBound: the bytes of the targets each pass bound, from GraphicsDevice::targetsBoundSinceMark.
#include "common/pass_bound.h"

#include <algorithm>
#include <cstdio>

#include "common/build_report.h"

namespace fxport::demo {

void PassBound::begin() {
    if (device) device->markBoundTargets();
}

void PassBound::end(const std::string& pass) {
    if (!device) return;
    double bytes = 0;
    for (const RenderTargetBinding& binding : device->targetsBoundSinceMark()) {
        if (const auto* target = dynamic_cast<const RenderTarget2D*>(binding.RenderTarget))
            bytes += double(RenderTargetBytes(target->Width(), target->Height(), 1, target->Format(), target->DepthStencilFormat()));
        else if (const auto* cube = dynamic_cast<const RenderTargetCube*>(binding.RenderTarget))
            bytes += double(RenderTargetBytes(cube->Size(), cube->Size(), 1, cube->Format(), cube->DepthStencilFormat()));
    }
    writes_[pass].push_back(bytes);
}

double PassBound::bytesPerRun(const std::string& pass) {
    auto found = writes_.find(pass);
    if (found == writes_.end() || found->second.empty()) return 0.0;
    std::vector<double> runs = found->second;
    std::sort(runs.begin(), runs.end());
    const std::size_t n = runs.size();
    return n % 2 ? runs[n / 2] : (runs[n / 2 - 1] + runs[n / 2]) / 2;
}

std::string PassBound::columns(const std::string& pass, double medianMs) {
    if (writes_.find(pass) == writes_.end()) return {};
    const double bytes = bytesPerRun(pass);
    char text[128];
    if (fillRateGBps > 0) {
        const double boundMs = bytes / (fillRateGBps * 1e9) * 1e3;
        std::snprintf(text, sizeof text, "  %9.2f MB  bound %8.3f ms  x%.1f", bytes / 1e6, boundMs,
                      boundMs > 0 ? medianMs / boundMs : 0.0);
    } else {
        std::snprintf(text, sizeof text, "  %9.2f MB", bytes / 1e6);
    }
    return text;
}

}  // namespace fxport::demo
