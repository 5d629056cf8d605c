// XNA's GraphicsAdapter and DisplayMode: what games ask before choosing a back-buffer size
// (`GraphicsAdapter.DefaultAdapter.CurrentDisplayMode.Width`). With a display (GLFW built in and a
// monitor reachable) they are the primary monitor's modes. Headless there is no monitor: the one
// mode reported is 1920x1080 (a common desktop), so a game sizing its back buffer from it runs the
// same way everywhere; IsHeadless() says which answer it is.
#pragma once

#include <vector>

#include "fxport/graphics/surface_format.h"
#include "fxport/math/rectangle.h"

namespace fxport {

struct DisplayMode {
    int Width = 0;
    int Height = 0;
    SurfaceFormat Format = SurfaceFormat::Color;
    int RefreshRate = 60;  // fxport addition (Hz); XNA's has none

    float AspectRatio() const { return Height > 0 ? float(Width) / float(Height) : 0.0f; }
    // XNA's title-safe area of a PC display: the whole screen.
    Rectangle TitleSafeArea() const { return Rectangle(0, 0, Width, Height); }
    bool operator==(const DisplayMode&) const = default;
};

class GraphicsAdapter {
public:
    // XNA's GraphicsAdapter.DefaultAdapter (and Adapters: this one).
    static GraphicsAdapter& DefaultAdapter();
    static std::vector<GraphicsAdapter*> Adapters() { return {&DefaultAdapter()}; }

    DisplayMode CurrentDisplayMode() const;
    // Every mode the monitor lists (Color format), smallest first; headless the one mode.
    std::vector<DisplayMode> SupportedDisplayModes() const;
    bool IsDefaultAdapter() const { return true; }
    // Whether the monitor is widescreen (aspect above 1.6), as XNA's IsWideScreen.
    bool IsWideScreen() const { return CurrentDisplayMode().AspectRatio() > 1.6f; }
    // fxport: no monitor was found (the modes are the headless 1920x1080 one).
    bool IsHeadless() const;

private:
    GraphicsAdapter() = default;
};

}  // namespace fxport
