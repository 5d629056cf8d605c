// fxdemo pointlights --check (fxport, not part of the seed): double-precision CPU references of every
// pass of the last frame, written from the effects (hlsl/zima-lights) under Direct3D 9's rules, and
// compared pixel by pixel with what the GPU wrote (read back):
//   G-buffer   RenderGBuffer.fx over the Scene model, rasterised on the CPU (ClearGBuffer.fx where no
//              triangle covers): colorRT (texture, specularIntensity), normalRT (normal, specularPower),
//              depthRT (z/w);
//   lightRT    DirectionalLight.fx + PointLight.fx for every light drawn (+ SpotLight.fx with --spot),
//              from the GPU's G-buffer; also reported alone where only the directional light reaches;
//   final      CombineFinal.fx from the GPU's colorRT and lightRT (the back buffer).
// D3D9 pixel centres as the runtime emulates them: pixel (x, y) samples at (x, y + 1/256) in D3D9
// screen space, so a full-screen quad's texCoord - halfPixel lands on the centre of texel (x-1, y-1)
// across and 1/256 texel below it. Each pixel's reference is an interval [lo, hi] per channel: the hull over what
// D3D9 leaves open (sample points within 1/256 pixel: vertex snapping and edges; 8-bit rounding within
// float error of a half; the 1/256 bilinear weight; mip level choice), so a pass's bound is exact
// except for those. Each target's check also shifts the GPU image by one pixel in x and in y and
// requires that the shifted image fails on at least half of the samples where it differs from the
// unshifted one by more than the format's rounding: the bounds are tight enough to see a shift.
#pragma once

namespace DeferredLighting {

class Game1;

// Prints one line per target and PASS/FAIL; returns true when every target passes. `spot`: the frame
// drew the spot light (--spot), whose parameters are those of DeferredRenderer::DrawLights at `time`.
bool CheckPasses(Game1& game, bool spot, double time);

}  // namespace DeferredLighting
