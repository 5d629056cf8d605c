// fxdemo pointlights --check (fxport, not part of the seed): a CPU reference of the light pass.
// From the G-buffer the GPU wrote (read back), the camera and the lights DrawLights drew, computes
// lightRT as DirectionalLight.fx + PointLight.fx do under Direct3D 9's rules (pixel centres at
// integer coordinates, so texCoord - halfPixel lands on the centre of texel (x-1, y-1)), each light
// clamped to [0,1] and added in 8 bits, and compares it with the GPU's lightRT. A light volume that
// misses pixels (wrong cull mode with the camera inside a light, a flipped target) shows up as
// pixels darker than the reference.
#pragma once

namespace DeferredLighting {

class Game1;

// Prints the comparison; returns true when it passes.
bool CheckLightMap(Game1& game);

}  // namespace DeferredLighting
