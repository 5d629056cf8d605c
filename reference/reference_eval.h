// How one pixel of a CPU reference is evaluated, and how far the GPU may honestly be from it.
//
// A reference pixel is a function of the pass's inputs written from the HLSL (deferred_reference.h).
// Three things make "the" D3D9 result less than a single number, and the driver here accounts for
// each instead of widening a global bound:
//
//  * Decisions D3D leaves to the hardware at exact boundaries: which texel a point sample takes when
//    its coordinate is within kPointBand of a texel edge, which triangle covers a pixel whose centre
//    is within a rasteriser's snapping distance of an edge, a shader branch whose two sides are
//    within float rounding of each other. The pixel function asks Eval::choose(n) at each; the driver
//    runs every combination (a small tree) and the reference is the hull [lo, hi] of the leaves.
//  * Inputs the GPU does not see exactly: a linear sample of an 8-bit texture is rounded to 8 bits
//    and its weights to 1/256 (measured on llvmpipe; GPUs quantise weights the same way), texels of
//    an intermediate target in the end-to-end test are only known to their own tolerance. Each
//    sample is registered with Eval::read(value, uncertainty); the driver re-runs the pixel with each
//    read channel moved by +-uncertainty and adds the largest changes (a first-order, L1 bound).
//  * Rasteriser snapping of non-full-screen geometry: vertices are snapped to 1/256 pixel, so
//    varyings are evaluated up to 1/512 pixel from the exact D3D9 sample point. With
//    EvalOptions::rasterSlack the driver re-runs the pixel at +-1/512 pixel in x and in y.
//
// The result's slack is what the GPU may differ by on top of the target format's own bound.
#pragma once

#include <functional>
#include <vector>

#include "reference/ref_math.h"

namespace fxport::reference {

// A reference value D3D9 leaves in [lo, hi] (lo == hi almost everywhere). `exact` marks values a
// pass writes as constants (Clear.fx, cleared targets): they carry no uncertainty downstream.
struct Range4 {
    V4 lo, hi;
    bool exact = false;
    static Range4 of(V4 v) { return {v, v, false}; }
    static Range4 exactly(V4 v) { return {v, v, true}; }
};
Range4 hull(const Range4& a, const Range4& b);
// Range4 * s, channel by channel, for a scalar range [s0, s1] (the products' min and max).
Range4 scaleByRange(V4 v, double s0, double s1);

class Eval {
public:
    // One of `arity` outcomes D3D does not fix; 0 is the exact-arithmetic one.
    int choose(int arity);
    // A shader comparison whose exact outcome is `exact`; when the compared values differ by less
    // than `eps` (float rounding), either outcome is admissible.
    bool decide(bool exact, double margin, double eps);
    // A sampled value and how far the GPU's own value may be from it (per channel, >= 0).
    V4 read(V4 value, V4 uncertainty);
    Range4 read(Range4 value, V4 uncertainty);
    // Where, relative to the exact D3D9 sample point, varyings of rasterised geometry are evaluated
    // in this run (pixels).
    V2 pixelShift() const { return shift_; }

private:
    friend struct Evaluator;
    std::vector<int> prefix_;
    std::vector<int> arities_;
    std::size_t next_ = 0;
    bool logReads_ = false;
    std::vector<V4> readLog_;
    int readIndex_ = 0;
    int perturbRead_ = -1;
    int perturbChannel_ = 0;
    double perturbAmount_ = 0;
    V2 shift_;
};

struct EvalOptions {
    bool rasterSlack = false;
    // Results are clamped to this range before comparing runs (UNORM targets: [0, 1]).
    double clampLo = -1e300, clampHi = 1e300;
};

struct PixelResult {
    V4 lo, hi;      // hull of the D3D9-admissible results
    V4 slack;       // first-order effect of input uncertainties and snapping
    bool exact = false;
    int leaves = 1; // how many admissible decision paths (1 = unambiguous)
};

using PixelFunction = std::function<Range4(Eval&)>;
PixelResult evaluatePixel(const PixelFunction& fn, const EvalOptions& options);

}  // namespace fxport::reference
