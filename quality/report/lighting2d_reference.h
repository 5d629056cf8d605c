// The exact image of a lighting2d scene (seed 002), computed on the CPU: each light's visibility by
// marching the shadow-caster bitmap (a grid walk along the straight line from the light to the
// pixel; the first caster texel it enters, alpha >= 0.01 as in Unwrap.fx, is the occluder), the
// seed's light model (PointLight.fx / SpotLight.fx: (1 - d / Radius) * Power, the spot's cone
// falloff, the Bias), no blur, and the targets' clamps (each light's map and the sum in [0, 1]),
// then LightBlend.fx's minimum light and the shadow casters drawn over it. Pixel (x, y) sits at
// screen position (x + 1/256, y + 1/256), as the runtime's D3D9 pixel centres put it.
#pragma once

#include <vector>

#include "lighting2d/light_renderer.h"

namespace fxport::report {

// background and casters: the GPU's backBufferCache and midGroundTarget (W x H), the scene's
// inputs. Returns RGB in [0, 1], W x H x 3.
std::vector<double> lighting2dReference(const _2DLightingSystem::LightRenderer& renderer, const std::vector<Color>& background,
                                        const std::vector<Color>& casters, int W, int H);

}  // namespace fxport::report
