// Procedural textures of the scene's materials. Each material has three maps, as the tutorial's
// GBuffer.fx samples them (hlsl/xna-deferred/GBuffer.fx, PS):
//   albedo   ("Texture")     RGB = colour; A = 255. GBuffer.fx overwrites Albedo.w with the specular
//                            map's .x, so the albedo's alpha is never read; it is kept opaque.
//   normal   ("NormalMap")   tangent-space normal encoded n * 0.5 + 0.5, +Z out of the surface,
//                            +X towards increasing u, +Y towards the top of the image (decreasing
//                            v): glTF's convention ("OpenGL", green up); flat = (128, 128, 255).
//   specular ("SpecularMap") R = specular intensity (-> GBuffer target 0 .w),
//                            G = specular power / 255 (-> target 1 .w; the light shaders read
//                            SpecularPower = encodedNormal.w * 255), B = 0, A = 255.
// All maps tile seamlessly (the GBuffer samplers use WRAP).
#pragma once

#include "image.h"

namespace fxport::content {

struct MaterialTextures {
    Image albedo;
    Image normal;
    Image specular;
};

// Encodes a specular intensity in [0, 1] and a specular power in [1, 255] as a specular-map texel.
Rgba SpecularTexel(float intensity, float power);

// Tangent-space normal map from a height field: slopes by central differences (wrapping),
// scaled by `strength` (height units per texel -> slope).
Image NormalMapFromHeight(const HeightField& height, float strength);

// 2 x 2 ceramic floor tiles in a checker of two glazes, with recessed grout.
MaterialTextures MakeFloorTiles(int size);
// Running-bond bricks, 4 across and 8 rows per repeat, with recessed mortar.
MaterialTextures MakeWallBricks(int size);
// Polished veined stone (marble-like), for the pillar shafts and the spheres.
MaterialTextures MakeStone(int size);
// A wooden crate face: frame, horizontal planks, a diagonal brace and nails. Mapped 0..1 per face.
MaterialTextures MakeWoodCrate(int size);

}  // namespace fxport::content
