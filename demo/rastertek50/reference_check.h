// fxport addition (not in the seed): `fxdemo rastertek50 --check` compares the last frame with an
// independent double-precision CPU reference:
//   - G-buffer normal target: the cube rasterised on the CPU (D3D10 pixel centres, top-left rule,
//     clockwise front faces, LH matrices built here from the seed's constants, not D3DClass's),
//     normal = normalize(n * (float3x3)world): coverage mismatches and max normal error;
//   - G-buffer colour target: the generated texture sampled trilinearly (wrap) at the perspective-
//     correct texcoord, LOD from 2x2-quad derivatives: max / mean / 99th percentile error;
//   - back buffer: light.fx evaluated on the GPU's own G-buffer texels (point sampling at pixel
//     centres): saturate(colour * saturate(dot(normal, -lightDirection))), 8-bit rounding.
#pragma once

#include <vector>

namespace Rastertek50 {

class ApplicationClass;

// Prints one line per check; returns true when all are within their bounds.
bool RunReferenceCheck(ApplicationClass& application);

// fxport (fxdemo report): the back buffer of the last frame as it would be without the G-buffer's
// precision limits, RGB in [0, 1], W x H x 3, top row first: the cube rasterised and textured here
// as above, lit by light.fx's saturate(colour * saturate(dot(normal, -lightDirection))) with the
// exact normal. For even sizes (the ortho window then maps pixel (x, y) to texel (x, y)).
std::vector<double> ReferenceImage(ApplicationClass& application);

}  // namespace Rastertek50
