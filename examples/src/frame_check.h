// The example's pixel check: what its frame must look like, computed on the CPU in double precision
// by ray-casting the cube (not by rasterising it), lit with XNA's BasicEffect equation, then the
// two post effects applied to 8-bit values as the render targets hold them.
#pragma once

#include <string>
#include <vector>

#include "fxport/math.h"

namespace example {

struct FrameCheck {
    int compared = 0;        // pixels away from the cube's edges (edges depend on rasterisation)
    int mismatches = 0;      // compared pixels off by more than the tolerance in any channel
    int maxDifference = 0;   // largest channel difference among compared pixels
    int notOpaque = 0;       // pixels whose alpha is not 255 (the saved frame must be opaque)
    int cubePixels = 0;      // compared pixels that show the cube
    int backgroundPixels = 0;
    int total = 0;
    bool passed() const;
    std::string summary() const;
};

// `pixels`: the frame, top row first, `width` x `height`, drawn at game time `totalSeconds`.
FrameCheck checkFrame(const std::vector<fxport::Color>& pixels, int width, int height, double totalSeconds);

}  // namespace example
