// The GPU side of the render tests (the comparison itself is reference/ref_image.h): converting the
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

#include "reference/d3d9_sampling.h"
#include "reference/deferred_reference.h"
#include "fxport/graphics.h"
#include "reference/reference_eval.h"
#include "reference/ref_image.h"
#include "reference/texel_bytes.h"

namespace fxport::render_test {

// The CPU references (V4, Range4, Eval, the deferred passes ...) are reference/'s, used here unqualified.
using namespace fxport::reference;

M4 toM4(const Matrix& m);
V3 toV3(Vector3 v);
V4 toV4(Vector4 v);
V2 toV2(Vector2 v);

TexelFormat texelFormat(SurfaceFormat f);
int channelCount(SurfaceFormat f);

// A CPU texture holding what the GPU stores for `values` in format f (rounded to 8/16 bits, or
// float), the missing channels read as 1.
CpuTexture quantize(int width, int height, SurfaceFormat f, const std::function<V4(int x, int y)>& values);
// Uploads (level 0 / one face) in the texture's format; the CPU texture must come from quantize()
// with that format.
void upload(Texture2D& texture, const CpuTexture& data);
void upload(TextureCube& texture, CubeMapFace face, const CpuTexture& data);
CpuTexture readBack(const Texture2D& texture);
CpuTexture readBack(const TextureCube& texture, CubeMapFace face);

// The references are reference/ref_image.h's RefImage; this evaluates one for a target format.
using ReferencePixel = std::function<Range4(Eval&, PixelPos)>;
// Evaluates every pixel (UNORM formats are clamped to [0, 1] as the target does).
RefImage referenceImage(int width, int height, SurfaceFormat format, bool rasterSlack, const ReferencePixel& pixel);
// Prints the numbers (stdout) and records them as test properties (<pass>.max_error, ...).
void report(const Comparison& c);

}  // namespace fxport::render_test
