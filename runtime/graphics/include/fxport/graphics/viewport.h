// Viewport: the part of the render target drawn to, in pixels from the top-left corner, and the
// depth range.
#pragma once

#include "fxport/math.h"

namespace fxport {

struct Viewport {
    int X = 0;
    int Y = 0;
    int Width = 0;
    int Height = 0;
    float MinDepth = 0;
    float MaxDepth = 1;

    Viewport() = default;
    Viewport(int x, int y, int width, int height) : X(x), Y(y), Width(width), Height(height) {}
    explicit Viewport(const Rectangle& r) : X(r.X), Y(r.Y), Width(r.Width), Height(r.Height) {}
    Rectangle Bounds() const { return Rectangle(X, Y, Width, Height); }
    float AspectRatio() const { return Height == 0 ? 0.0f : float(Width) / float(Height); }
    bool operator==(const Viewport&) const = default;
};

}  // namespace fxport
