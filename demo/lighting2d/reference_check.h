// fxdemo lighting2d --check (fxport, not part of the seed): CPU references, in double precision,
// of the per-light steps, written from the HLSL (hlsl/lighting2d/*.fx) and the host notes
// (docs/lighting2d-host-notes.md), compared with the targets the GPU wrote (read back with GetData):
//   unwrap     Unwrap.fx / UnwrapSpotlight.fx from the shadow casters the GPU drew (midGroundTarget);
//   occlusion  the Min collapse of the unwrap rows (white clear), from the reference unwrap and,
//              exactly, from the GPU's own unwrap;
//   light map  PointLight.fx / SpotLight.fx from the GPU's occlusion map (staged: each step's
//              reference starts from the GPU's input to that step);
//   blur       HorizontalBlur.fx from the GPU's light map, VerticalBlur.fx from the GPU's
//              horizontal blur (LinearClamp bilinear filtering).
// Pixel centres are D3D9's as the runtime emulates them: pixel (x, y) of a destination rectangle of
// w x h interpolates texCoord = ((x + 1/256) / w, (y + 1/256) / h) (docs/DESIGN.md "runtime").
#pragma once

#include <cstdint>
#include <vector>

#include "lighting2d/light_renderer.h"

namespace _2DLightingSystem {

// One light's targets right after its LightMap step, and the uniforms the host gave the effects.
struct LightCapture {
    bool valid = false;
    bool isSpot = false;
    float posX = 0, posY = 0, power = 0, radius = 0;
    float lightDirAngle = 0, innerAngle = 0, outerAngle = 0, angleBias = 0;  // spot only
    std::vector<std::uint16_t> unwrap;     // W x W x RGBA16F
    std::vector<std::uint16_t> occlusion;  // W x 1 x RGBA16F
    std::vector<Color> lightMap;           // postProcessTarget, W x H Color
    std::vector<Color> hBlur, vBlur;       // horizontalBlurTarget, verticalBlurTarget
};

struct CheckCapture {
    LightCapture spot, point;
};

// Called from LightRenderer::afterLight (after the light's steps, before accumulation).
void CaptureLight(LightRenderer& renderer, const Light& light, bool isSpot, LightCapture& out);

// Prints max / RMS per target and PASS/FAIL; returns true when everything passes.
bool CheckLighting(LightRenderer& renderer, const CheckCapture& capture);

}  // namespace _2DLightingSystem
