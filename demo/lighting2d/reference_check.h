// fxdemo lighting2d --check (fxport, not part of the seed): CPU references, in double precision,
// of every step of the last frame, written from the HLSL (hlsl/lighting2d/*.fx) and the host notes
// (docs/lighting2d-host-notes.md), compared with the targets the GPU wrote (read back with GetData).
// For every light of the scene (each spot light, then each point light, as DrawLitScene draws them):
//   unwrap     Unwrap.fx / UnwrapSpotlight.fx from the shadow casters the GPU drew (midGroundTarget);
//   occlusion  the Min collapse of the unwrap rows (white clear), from the reference unwrap and,
//              exactly, from the GPU's own unwrap;
//   light map  PointLight.fx / SpotLight.fx from the GPU's occlusion map (staged: each step's
//              reference starts from the GPU's input to that step);
//   blur       HorizontalBlur.fx from the GPU's light map, VerticalBlur.fx from the GPU's
//              horizontal blur (LinearClamp bilinear filtering).
// Then, for the frame:
//   accumulation  AccumulateLightMaps: lightMap = black + the sum of every light's blurred map tinted
//                 by its colour (SpriteBatch, BlendState.Additive, 8-bit saturating), from the GPU's
//                 blurred maps;
//   final         RenderFinalScene: LightBlend.fx (background * (light * (1 - MinLight) + MinLight))
//                 from the GPU's backBufferCache and lightMap, then the shadow casters drawn over it
//                 with AlphaBlend: the back buffer.
// Pixel centres are D3D9's as the runtime emulates them: pixel (x, y) of a destination rectangle of
// w x h interpolates texCoord = (x / w, (y + 1/256) / h) (docs/DESIGN.md "runtime").
// The light map, blur, accumulation and final references are per-pixel intervals; their checks also
// move the GPU image by one pixel in x and in y and require it to fail on at least half of the
// samples where it differs from the unshifted image by more than 1 LSB.
#pragma once

#include <cstdint>
#include <vector>

#include "lighting2d/light_renderer.h"

namespace _2DLightingSystem {

// One light's targets right after its LightMap step, and the uniforms the host gave the effects.
struct LightCapture {
    bool valid = false;
    bool isSpot = false;
    Color color;  // the tint AccumulateLightMaps draws the blurred map with
    float posX = 0, posY = 0, power = 0, radius = 0;
    float lightDirAngle = 0, innerAngle = 0, outerAngle = 0, angleBias = 0;  // spot only
    std::vector<std::uint16_t> unwrap;     // W x W x RGBA16F
    std::vector<std::uint16_t> occlusion;  // W x 1 x RGBA16F
    std::vector<Color> lightMap;           // postProcessTarget, W x H Color
    std::vector<Color> hBlur, vBlur;       // horizontalBlurTarget, verticalBlurTarget
};

// Every light of the last frame, in drawing order.
struct CheckCapture {
    std::vector<LightCapture> lights;
};

// Called from LightRenderer::afterLight (after the light's steps, before accumulation).
void CaptureLight(LightRenderer& renderer, const Light& light, bool isSpot, LightCapture& out);

// Prints max / RMS per target and PASS/FAIL; returns true when everything passes. Call it before
// anything else draws (it reads the back buffer).
bool CheckLighting(LightRenderer& renderer, const CheckCapture& capture);

}  // namespace _2DLightingSystem
