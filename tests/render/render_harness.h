// The GPU side of the render tests and the comparison with the CPU references: converting the
// runtime's float values to the references' doubles, uploading CPU textures in the demo's surface
// formats (quantised exactly as the GPU stores them), reading targets back, evaluating a reference
// image, comparing and reporting max / RMS error per pass.
//
// Bounds (per pixel and channel): |GPU - reference| <= formatBound + slack, where formatBound is
//   Color (8-bit):    1/255   (0.5/255 rounding of the target + float arithmetic, with room)
//   Rgba64 (16-bit):  1/65535 (0.5 LSB rounding + float arithmetic)
//   Single/Vector2:   1e-5 relative
// and slack is what reference_eval.h derives for that pixel (8-bit linear filtering, bilinear
// weight quantisation, rasteriser snapping, upstream tolerance), 0 where none applies. A pixel
// that D3D leaves ambiguous is compared with the hull of its admissible values.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "d3d9_sampling.h"
#include "deferred_reference.h"
#include "fxport/graphics.h"
#include "reference_eval.h"

namespace fxport::render_test {

M4 toM4(const Matrix& m);
V3 toV3(Vector3 v);
V4 toV4(Vector4 v);
V2 toV2(Vector2 v);

TexelFormat texelFormat(SurfaceFormat f);
int channelCount(SurfaceFormat f);
// The per-pixel bound of a format (value = the reference value, for relative bounds).
double formatBound(TexelFormat f, double value);

// A CPU texture holding what the GPU stores for `values` in format f (rounded to 8/16 bits, or
// float), the missing channels read as 1.
CpuTexture quantize(int width, int height, SurfaceFormat f, const std::function<V4(int x, int y)>& values);
// Uploads (level 0 / one face) in the texture's format; the CPU texture must come from quantize()
// with that format.
void upload(Texture2D& texture, const CpuTexture& data);
void upload(TextureCube& texture, CubeMapFace face, const CpuTexture& data);
CpuTexture readBack(const Texture2D& texture);
CpuTexture readBack(const TextureCube& texture, CubeMapFace face);

struct RefImage {
    int width = 0, height = 0;
    SurfaceFormat format = SurfaceFormat::Color;
    double boundScale = 1;  // formatBound multiplier (several rounded fragments blended into one texel)
    std::vector<PixelResult> pixels;
    const PixelResult& at(int x, int y) const { return pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)]; }
};
using ReferencePixel = std::function<Range4(Eval&, PixelPos)>;
// Evaluates every pixel (UNORM formats are clamped to [0, 1] as the target does).
RefImage referenceImage(int width, int height, SurfaceFormat format, bool rasterSlack, const ReferencePixel& pixel);
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
    // How discriminating the bounds are: the fraction of samples that fail when the GPU image is
    // moved one pixel to the right, against the fraction whose reference differs from its left
    // neighbour's by more than the bound (what a one-pixel shift could at best reveal).
    double shiftedFailureFraction = 0, shiftVisibleFraction = 0;
};
// Compares the first min(channels of the format, maxChannels) channels.
Comparison compare(const std::string& pass, const CpuTexture& gpu, const RefImage& ref, int maxChannels = 4);
// Prints the numbers (stdout) and records them as test properties (<pass>.max_error, ...).
void report(const Comparison& c);

}  // namespace fxport::render_test
