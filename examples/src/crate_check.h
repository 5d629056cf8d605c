// The crate game's pixel check: the frame computed on the CPU in double precision by ray-casting
// the crate (not by rasterising it): the face a ray enters, the texture coordinate the .x file gives
// that point, the DXT1 block's colour there, as BasicEffect without lighting shows it.
#pragma once

#include <string>
#include <vector>

#include "fxport/math.h"

namespace example {

struct CrateCheck {
    int compared = 0;       // pixels away from the crate's edges and the texture's block borders
    int mismatches = 0;     // compared pixels off by more than the tolerance in any channel
    int maxDifference = 0;  // largest channel difference among compared pixels
    int cratePixels = 0;    // compared pixels that show the crate
    int colours = 0;        // of the four block colours, how many were seen
    bool passed() const { return mismatches == 0 && cratePixels > 100 && colours == 4 && compared > cratePixels; }
    std::string summary() const;
};

CrateCheck checkCrateFrame(const std::vector<fxport::Color>& pixels, int width, int height);

}  // namespace example
