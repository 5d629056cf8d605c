// See graphics_adapter.h: the primary monitor's modes through the platform, or the headless one.
#include "fxport/graphics/graphics_adapter.h"

#include <algorithm>

#include "fxport/platform/graphics_context.h"

namespace fxport {

namespace {

const DisplayMode kHeadlessMode{1920, 1080, SurfaceFormat::Color, 60};

struct Monitor {
    bool found = false;
    platform::DisplayModeInfo current;
    std::vector<platform::DisplayModeInfo> modes;
};

Monitor askMonitor() {
    Monitor m;
    m.found = platform::primaryDisplayModes(m.modes, m.current);
    return m;
}

DisplayMode modeOf(const platform::DisplayModeInfo& info) { return DisplayMode{info.width, info.height, SurfaceFormat::Color, info.refreshRate}; }

}  // namespace

GraphicsAdapter& GraphicsAdapter::DefaultAdapter() {
    static GraphicsAdapter adapter;
    return adapter;
}

bool GraphicsAdapter::IsHeadless() const { return !askMonitor().found; }

DisplayMode GraphicsAdapter::CurrentDisplayMode() const {
    const Monitor m = askMonitor();
    return m.found ? modeOf(m.current) : kHeadlessMode;
}

std::vector<DisplayMode> GraphicsAdapter::SupportedDisplayModes() const {
    const Monitor m = askMonitor();
    if (!m.found) return {kHeadlessMode};
    std::vector<DisplayMode> out;
    for (const platform::DisplayModeInfo& info : m.modes) out.push_back(modeOf(info));
    std::sort(out.begin(), out.end(), [](const DisplayMode& a, const DisplayMode& b) {
        return a.Width != b.Width ? a.Width < b.Width : a.Height != b.Height ? a.Height < b.Height : a.RefreshRate < b.RefreshRate;
    });
    return out;
}

}  // namespace fxport
