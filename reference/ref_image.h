// The one CPU reference image: per pixel and channel the interval [lo, hi] of values a correct GPU
// may have written (D3D leaves some choices open, inputs are known only to their own tolerance), its
// comparison with an image read back from the GPU, and the one-pixel-shift check that shows the
// bounds are tight enough to see a misplaced image. The render tests (values in [0, 1] or float,
// with the format's bound and a per-sample slack on top) and the demos' --check (8-bit targets in
// LSB, the bound folded into [lo, hi]) both use it.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "reference/d3d9_sampling.h"
#include "reference/reference_eval.h"

namespace fxport::reference {

struct RefImage {
    int width = 0, height = 0, channels = 4;
    std::vector<double> lo, hi;  // per sample (pixel-major, then channel): the admissible values
    // What the render tests' references add (empty in the demos' checks):
    std::vector<double> slack;         // per sample: allowed on top of the format's bound (input uncertainty, snapping)
    std::vector<unsigned char> exact;  // per pixel: a constant the pass writes (no uncertainty downstream)
    std::vector<int> leaves;           // per pixel: how many admissible decision paths (1 = unambiguous)
    TexelFormat format = TexelFormat::Unorm8;  // the render tests' format bound (formatBound)
    double boundScale = 1;  // formatBound multiplier (several rounded fragments blended into one texel)

    RefImage() = default;
    RefImage(int w, int h, int c)
        : width(w), height(h), channels(c), lo(std::size_t(w) * std::size_t(h) * std::size_t(c)), hi(lo.size()) {}
    std::size_t index(int x, int y, int c) const {
        return (std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels) + std::size_t(c);
    }
    void set(int x, int y, int c, double l, double h) { lo[index(x, y, c)] = l, hi[index(x, y, c)] = h; }
    double slackAt(std::size_t i) const { return slack.empty() ? 0.0 : slack[i]; }
    bool exactAt(int x, int y) const { return !exact.empty() && exact[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
    int leavesAt(int x, int y) const { return leaves.empty() ? 1 : leaves[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};

// ---- the render tests: references evaluated pixel by pixel (reference_eval.h) -----------------

using ImagePixel = std::function<Range4(Eval&, int x, int y)>;
// Evaluates every pixel; UNORM formats are clamped to [0, 1] as the target does. `channels`: the
// format's stored channels.
RefImage evaluateImage(int width, int height, TexelFormat format, int channels, bool rasterSlack, const ImagePixel& pixel);
// The reference as the next pass's input: the middle of each range, rounded as the format stores
// it, with tolerance = half the range + formatBound + slack (0 for constants a pass writes).
CpuTexture asInput(const RefImage& ref);

struct Comparison {
    std::string pass;
    long samples = 0;         // pixel-channels compared
    double maxError = 0;      // distance from the reference (hull), largest
    double rmsError = 0;
    double maxAllowed = 0;    // largest per-pixel bound used
    double maxSlack = 0;
    long slackSamples = 0;    // pixel-channels whose slack exceeds the format bound
    long ambiguousPixels = 0; // pixels whose reference is a range (D3D leaves the choice open)
    long wideRangePixels = 0; // ... of which the range is wider than the format bound
    double medianAllowed = 0; // typical per-pixel bound
    double p95Allowed = 0;    // 95th percentile of the per-pixel bound
    double maxRelError = 0;   // float targets: largest error / |reference| (0 for UNORM targets)
    long failures = 0;
    std::string failureText;  // the first failures: pixel, channel, GPU, reference, bound
    // The one-pixel-shift check: the fraction of samples that fail when the GPU image is moved one
    // pixel to the right, against the fraction whose reference differs from its left neighbour's
    // by more than the bound (what a one-pixel shift could at best reveal).
    double shiftedFailureFraction = 0, shiftVisibleFraction = 0;
};
// |GPU - [lo, hi]| <= boundScale * formatBound + slack per sample; the first min(channels,
// maxChannels) channels.
Comparison compare(const std::string& pass, const CpuTexture& gpu, const RefImage& ref, int maxChannels = 4);

// ---- the demos' --check: 8-bit images in LSB, bounds already in [lo, hi] ----------------------

// A read-back image as doubles in the reference's units (8-bit targets: LSB).
struct GpuImage {
    int width = 0, height = 0, channels = 4;
    std::vector<double> values;
    double at(int x, int y, int c) const {
        return values[(std::size_t(y) * std::size_t(width) + std::size_t(x)) * std::size_t(channels) + std::size_t(c)];
    }
    // From RGBA8 bytes (a Color target's GetData), width * height * 4 of them.
    static GpuImage fromRgba8(const unsigned char* rgba, int width, int height);
};

// Every sample inside its interval; and the GPU image moved by one pixel (in x, then in y) must fail
// on at least half of the samples where it differs from the unshifted image by more than
// `changeThreshold` (and the unshifted sample passed). `mask`: only these pixels (null: all).
// Prints what it found (name, samples outside, worst sample, the shift check) and returns pass.
bool checkImage(const char* name, const char* bound, const RefImage& ref, const GpuImage& gpu, double changeThreshold,
                const std::vector<char>* mask = nullptr);

// The one-pixel-shift check alone: the GPU image moved by one pixel (in x, then in y) must fall
// outside the intervals on at least half of the samples where it differs from the unshifted image
// by more than `changeThreshold` (and the unshifted sample is inside). Prints one line.
struct ShiftCheck {
    long changed[2] = {0, 0}, shiftedFails[2] = {0, 0};  // [0]: moved in x, [1]: in y
    bool seen() const {
        return changed[0] > 0 && changed[1] > 0 && 2 * shiftedFails[0] >= changed[0] && 2 * shiftedFails[1] >= changed[1];
    }
};
ShiftCheck shiftCheck(const RefImage& ref, const GpuImage& gpu, double changeThreshold, const std::vector<char>* mask = nullptr);
bool checkShift(const char* name, const RefImage& ref, const GpuImage& gpu, double changeThreshold);

// A LINEAR sample of an 8-bit texture drawn 1:1: texel (x0, y0) with weight 255/256 per axis, its
// right/lower neighbours with 1/256 (clamped to the image, or wrapped with `wrap`). The interval
// spans the texel and the filtered value, +-1 LSB where the texels differ (8-bit filters round after
// the horizontal lerps and again after the vertical one: seen on llvmpipe), within [0, 255].
// texel(i, j): the channel's value (LSB) of texel (i, j), i and j already inside the image.
void linearSample8(int width, int height, int x0, int y0, bool wrap, const std::function<double(int i, int j)>& texel,
                   double& lo, double& hi);

}  // namespace fxport::reference
