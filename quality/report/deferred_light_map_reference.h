// The exact light map of the XNA deferred demo (seed 000) for `fxdemo report`: what
// hlsl/xna-deferred's DirectionalLight.fx, SpotLight.fx and PointLight.fx add into the 8-bit
// LightMap target, with each shadowed light's exponential-shadow-map test replaced by the true
// visibility of the light, found by casting a ray against the scene's triangles.
//
// Inputs, and how exact they are:
//  * Surfaces: the G-buffer of the game's last frame, read back. It must be the float32 one
//    (GBufferFormats::Float32): the reference then starts from float32 positions, normals and
//    specular terms, not from a CPU rasterisation of the scene (normal and specular maps included);
//    what differs between settings is the G-buffer format, the shadow maps and the render size.
//  * Unshadowed lighting per pass: reference/'s double-precision pass references
//    (deferred_reference.h: directionalLightPixel, spotLightPixel, pointLightPixel with Shadows off,
//    the tutorial's quirks included -- the G-buffer read one texel up-left, the directional light's
//    Position.y = -(UV.x * 2 - 1), the spot cone test SL <= LightAngleCos), each pixel on its
//    exact-arithmetic path, with the game's own light and camera values.
//  * Light volumes: a spot or point light adds to a pixel once per cone/sphere triangle that its
//    rasteriser keeps there (the renderer's cull mode; the LightMap's own depth buffer is cleared,
//    so no depth test removes any): counted by casting the pixel's ray through the volume mesh.
//  * Visibility: 1 when no scene triangle lies between the light and the surface point that the
//    pass's depth sample stands for (the G-buffer texel one up-left, at that texel's own screen
//    position and depth), else 0. Bias: hits closer than kShadowRayStart (scene units) to the
//    surface are ignored, so that a float32 depth's error does not shadow its own surface. The
//    effects' ESM is soft and biased, so it differs near shadow edges: that is the knob's error.
//  * The LightMap is SurfaceFormat::Color with additive blending: each pass's output is clamped
//    to [0, 1] and the sum saturates at 1 after each pass, in the renderer's order.
#pragma once

#include <vector>

#include "deferred/game1.h"

namespace fxport::report {

// Scene units (the courtyard is about 40 wide): the shadow ray starts this far from the surface.
inline constexpr double kShadowRayStart = 0.02;

// Where the light map has no exact answer: the passes read the G-buffer one texel up-left of the
// pixel and shade the pixel's screen position at that texel's depth; where that texel shows
// another surface than the pixel's own texel (a silhouette), the shaded point floats off both and
// its shadow means nothing. Such a pixel is left out: its own and the up-left texel's surface
// points are farther apart than kUndefinedAt x the distance to the camera (one pixel's footprint
// is ~0.8 / height of it: 0.013 at 64 rows, on a surface facing the camera).
inline constexpr double kUndefinedAt = 0.05;

// The shadow terminator: a pixel that a shadowed light lights through its G-buffer normal (the
// mesh's smooth, interpolated normal) while the mesh facet under it faces away from the light. The
// ray cast, exact for the faceted mesh, shadows such a point (the ray leaves through the object's
// own triangles); an exponential shadow map, biased and soft, lights it. Neither is wrong for the
// mesh the effects see; the two answers simply differ there, whatever the shadow map's size. The
// facet is the scene triangle that the camera ray meets at the pixel's surface point.
struct ExactLightMap {
    std::vector<double> rgba;  // RGBA per pixel (A = specular), rows from the top, in [0, 1]
    std::vector<char> defined; // per pixel: 0 at silhouettes (see kUndefinedAt)
    std::vector<char> terminator;  // per pixel: 1 on a shadowed light's terminator (above)
    // The same light map with each shadowed light's visibility replaced by what the effects'
    // exponential shadow test gives with an exact, infinitely fine shadow map: ShadowFactor =
    // exp(DP/2 * d_occ/DP) * exp(-DP/2 * (max(.01, d)/DP - DepthBias)) = exp(-(d - d_occ)/2 + DP
    // DepthBias/2), d_occ the distance from the light to the first scene triangle towards the
    // point (ray cast), DP = DepthPrecision (the spot's far plane, the point light's radius). What
    // is left between the GPU and this is the shadow map's sampling; between this and `rgba`, the
    // exponential test itself (soft over a few units behind every caster, and its bias).
    std::vector<double> idealEsmRgba;
};

// At the game's back-buffer size. Throws ArgumentError when the game's G-buffer is not float32 or
// it has not drawn a frame.
ExactLightMap exactDeferredLightMap(TheCansinDeferredRenderer::Game1& game);

// The GPU's LightMap target of the game's last frame as RGBA doubles in [0, 1].
std::vector<double> readDeferredLightMap(TheCansinDeferredRenderer::Game1& game);

}  // namespace fxport::report
