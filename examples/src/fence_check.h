// The fence game's pixel check: what its frame must look like, computed on the CPU in double
// precision. Each pixel's ray is cast against the fence and gate quads (texel by point sampling;
// kept when its alpha is above AlphaRef 128) and the crate's six planes (lit per pixel with XNA's default
// lighting rig), and the HUD text is checked against SpriteFont::MeasureString: ink inside the
// measured box, in each character's advance, on the line from the sky colour to white (premultiplied
// alpha blending); no ink outside.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "fxport/math.h"

namespace example {

struct FenceFrame {
    const std::vector<fxport::Color>* pixels = nullptr;  // top row first
    int width = 0;
    int height = 0;
    double totalSeconds = 0;  // game time of the last Update
    const std::vector<fxport::Color>* fenceTexels = nullptr;  // Fence.png as loaded, top row first
    int fenceWidth = 0;
    int fenceHeight = 0;
    // The HUD string's box: DrawString's position and MeasureString's size; and per character, the
    // pen's x before and after it (MeasureString of the string up to it), relative to the position.
    fxport::Vector2 textPosition;
    fxport::Vector2 textSize;
    std::vector<std::pair<float, float>> characterAdvances;  // empty pair for spaces is (x, x)
};

struct FenceFrameCheck {
    int total = 0;
    int compared = 0;            // pixels away from edges (edges depend on rasterisation)
    int mismatches = 0;          // compared pixels off by more than their tolerance
    int maxLitDifference = 0;    // the crate's lit pixels (tolerance kLitTolerance)
    int maxFlatDifference = 0;   // sky, fence boards and HUD background (tolerance kFlatTolerance)
    int notOpaque = 0;
    int crate = 0, sky = 0;      // seen directly
    int boards = 0, knots = 0;   // fence texels kept: alpha 255, alpha above 128 but below 255
    int holesShowingSky = 0, holesShowingCrate = 0, knotholes = 0;  // discarded: alpha 0; alpha 1..128
    int gateKept = 0, gateDiscarded = 0;  // of those, on the gate (AlphaTestEffect)
    // The HUD text.
    int textBoxPixels = 0, inkPixels = 0, inkOffBlendLine = 0;
    int inkLeft = 1 << 30, inkRight = -1, inkTop = 1 << 30, inkBottom = -1;
    int charactersWithoutInk = 0;
    std::string problems;  // one line per failed condition
    bool passed() const { return problems.empty(); }
    std::string summary() const;
};

FenceFrameCheck checkFenceFrame(const FenceFrame& frame);

}  // namespace example
