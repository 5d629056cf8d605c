// LightRenderer: the seed's LightRenderer.cs (seed 002, Parts 3-8), ported onto fxport in its own
// structure and names. The lines the seed lost (parameters, SetRenderTarget, Clear, End) come from
// the public LightRenderer port; see docs/lighting2d-host-notes.md.
//
//   lightRenderer.BeginDrawBackground();    ...draw background sprites...   lightRenderer.EndDrawBackground();
//   lightRenderer.BeginDrawShadowCasters(); ...draw shadow casters...       lightRenderer.EndDrawShadowCasters();
//   lightRenderer.DrawLitScene();           ...draw foreground / HUD...
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "fxport/framework.h"
#include "common/pass_timer.h"
#include "fxport/graphics.h"
#include "lighting2d/lights.h"

namespace _2DLightingSystem {

using namespace fxport;
using fxport::GraphicsDeviceManager;
using fxport::ContentManager;

class LightRenderer {
public:
    // fxport: XNA's GraphicsDeviceManager owns the device; here the Game does, so both are given.
    LightRenderer(GraphicsDeviceManager& _graphics, fxport::GraphicsDevice& device);

    void Initialize();
    void LoadContent(ContentManager& Content);

    void BeginDrawBackground();
    void EndDrawBackground() {}
    void BeginDrawShadowCasters();
    void EndDrawShadowCasters() {}
    void DrawLitScene();

    GraphicsDeviceManager& graphics;
    fxport::GraphicsDevice& GraphicsDevice;

    std::vector<SpotLight> spotLights;
    std::vector<PointLight> pointLights;

    std::unique_ptr<RenderTarget2D> backBufferCache;
    std::unique_ptr<RenderTarget2D> midGroundTarget;
    std::unique_ptr<RenderTarget2D> lightMap;
    std::unique_ptr<RenderTarget2D> unwrapTarget;
    std::unique_ptr<RenderTarget2D> occlusionMap;
    std::unique_ptr<RenderTarget2D> postProcessTarget;
    std::unique_ptr<RenderTarget2D> horizontalBlurTarget;
    std::unique_ptr<RenderTarget2D> verticalBlurTarget;

    // fxport (issue 6): unwrapSpotlight and spotLight are loaded when the first spot light is drawn,
    // unwrap and pointLight when the first point light is (nullptr until then).
    Effect* unwrapSpotlight = nullptr;
    Effect* unwrap = nullptr;
    Effect* spotLight = nullptr;
    Effect* pointLight = nullptr;
    Effect* horizontalBlur = nullptr;
    Effect* verticalBlur = nullptr;
    Effect* lightBlend = nullptr;

    BlendState collapseBlendState;

    float lightBias = -1.f;  // the developer must set it (seed, Part 5)
    float minLight = -1.f;   // the developer must set it (seed, Part 3)
    float minBlur = 0.0f;
    float maxBlur = 5.0f;

    // fxport additions (knobs of `fxdemo report`), read by Initialize: the number of rays, which is
    // the unwrap target's width and height (rays x samples per ray) and the occlusion map's width
    // (0: the screen width, as the seed), and the format of those two targets (the seed's
    // HdrBlendable; Color stores the distances in 8 bits, which the seed estimates at ~6 px at 720p).
    int rayCount = 0;
    // fxport (issue 16): the per-light screen-space steps (light map, both blurs, accumulation)
    // draw only inside the light's reach (a scissor rectangle, LightReach); outside it they would
    // write the clear colour, which the targets are cleared to. Same image; false draws them over
    // the whole screen as the seed does (fxdemo lighting2d --no-light-scissor).
    bool scissorLights = true;
    SurfaceFormat occlusionFormat = SurfaceFormat::HdrBlendable;
    int RayCount() const { return unwrapTarget ? unwrapTarget->Width() : 0; }

    // fxport: GPU time per step (PassTimer), and a hook that sees the targets after each light's
    // steps (for the debug images): called with the light and "spot"/"point".
    GpuTimer* gpuTimer = nullptr;
    void (*afterLight)(LightRenderer& renderer, const Light& light, bool isSpot, void* user) = nullptr;
    void* afterLightUser = nullptr;

private:
    void PrepareResources();
    void LoadLightEffects();
    void UnwrapShadowCasters(const SpotLight& sLight, float lightDirAngle);
    void UnwrapShadowCasters(const PointLight& pLight);
    void CreateOcclusionMap();
    void CreateLightMap(const SpotLight& sLight, float lightDirAngle);
    void CreateLightMap(const PointLight& pLight);
    void BlurLightMaps(const Light& light);
    void AccumulateLightMaps(const Light& light);
    void RenderFinalScene();
    Rectangle LightReach(const Light& light) const;
    // The rasterizer state of a per-light screen-space step: nullptr (SpriteBatch's default) or
    // the default with the scissor test on, ScissorRectangle set to `reach`.
    const RasterizerState* ScissorTo(const Rectangle& reach);
    RasterizerState scissorState;

    Rectangle fullScreen;
    Vector2 screenDims;
    std::unique_ptr<SpriteBatch> spriteBatch;
    // fxport (issue 6): where LoadLightEffects loads a light type's effects from, at its first light.
    ContentManager* content = nullptr;
};

}  // namespace _2DLightingSystem
