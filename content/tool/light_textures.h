// Textures of the lights and of SSAO, loaded by name in the tutorial's Game1 and SSAO classes:
//   SpotCookie, SquareCookie  (Content.Load<Texture2D>, seed 000 lines 1837-1838): spot light
//       attenuation cookies. SpotLight.fx reads tex2D(Cookie, LUV).r, where LUV is the pixel
//       projected into the light's 90-degree view (u right, v down) and sampled LinearClamp, so
//       every border texel is 0 (no light leaks past the clamp). Grey in R = G = B, A = 255.
//   RandomNormals             (Content.Load<Texture2D>, seed line 2785): random unit vectors
//       encoded n * 0.5 + 0.5 in RGB, A = 255. SSAO.fx samples it at UV * 200 and passes the
//       raw .xyz to reflect() without decoding (hlsl/xna-deferred/SSAO.fx, PS): this texture keeps
//       the usual encoding, as the tutorial's own asset (not in the seed) presumably did.
#pragma once

#include <cstdint>

#include "image.h"

namespace fxport::content {

// A soft round spot with concentric reflector rings, zero beyond 95% of the half-width.
Image MakeSpotCookie(int size);
// A square window of 2 x 2 panes (dark frame and mullions), soft edges, dark margin.
Image MakeSquareCookie(int size);
// size x size random unit vectors, uniform on the sphere, from a fixed seed.
Image MakeRandomNormals(int size, std::uint64_t seed);

}  // namespace fxport::content
