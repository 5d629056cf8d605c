// DeferredRenderer (seed 000, chapters 2-5, in its final form): clears and fills the G-buffer,
// accumulates the lights into the light map and composes the lit scene.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "deferred/Cameras/base_camera.h"
#include "deferred/Lights/light_manager.h"
#include "deferred/xna.h"

namespace TheCansinDeferredRenderer {

class DeferredRenderer {
    //Clear Shader
    Effect* Clear;
    //GBuffer Shader
    Effect* GBuffer;
    // fxport: the light shaders and volumes are loaded the first time a light of their type is
    // drawn (nullptr before), so a scene without spot or point lights never compiles their effects.
    //Directional Light Shader
    Effect* directionalLight = nullptr;
    //Point Light Shader
    Effect* pointLight = nullptr;
    //Spot Light Shader
    Effect* spotLight = nullptr;
    //Composition Shader
    Effect* compose;
    //LightMap BlendState
    BlendState LightMapBS;
    //GBuffer Targets
    std::vector<RenderTargetBinding> GBufferTargets;
    //GBuffer Texture Size
    Vector2 GBufferTextureSize;
    //Light Map Target
    std::unique_ptr<RenderTarget2D> LightMap;
    //Fullscreen Quad
    std::unique_ptr<FullscreenQuad> fsq;
    //Point Light Geometry
    Model* pointLightGeometry = nullptr;
    //Spot Light Geometry
    Model* spotLightGeometry = nullptr;

public:
    //Get GBuffer
    const std::vector<RenderTargetBinding>& getGBuffer() const { return GBufferTargets; }
    //Constructor
    // fxport: GBufferFormats are the three targets' formats (the seed's: Rgba64, Rgba64, Vector2).
    DeferredRenderer(GraphicsDevice& GraphicsDevice, ContentManager& Content, int Width, int Height,
                     std::array<SurfaceFormat, 3> GBufferFormats = {SurfaceFormat::Rgba64, SurfaceFormat::Rgba64,
                                                                    SurfaceFormat::Vector2});

    //Draw Scene Deferred
    void Draw(GraphicsDevice& GraphicsDevice, const std::vector<Model*>& Models, Lights::LightManager& Lights,
              BaseCamera& Camera, RenderTarget2D* Output);
    //Debug
    void Debug(GraphicsDevice& GraphicsDevice, SpriteBatch& spriteBatch);

    // fxport additions: the light map for fxdemo's debug sheet, and a GPU timer for the passes.
    RenderTarget2D& getLightMap() const { return *LightMap; }
    void setGpuTimer(GpuTimer* timer) { gpuTimer = timer; }

    // fxport additions (issue 6): frustum culling of the light volumes and what the last Draw did.
    // Whether the camera's frustum meets the light's volume (its geometry's bounding sphere under
    // the light's World); loads the volume's model if it was not yet. Always true with
    // frustumCulling off (the seed's behaviour: every light drawn, every shadow map made).
    bool frustumCulling = true;
    bool IsVisible(const Lights::SpotLight& light, const BaseCamera& Camera);
    bool IsVisible(const Lights::PointLight& light, const BaseCamera& Camera);
    struct FrameStats {
        int directionalLightsDrawn = 0;
        int spotLightsDrawn = 0, spotLightsCulled = 0;
        int pointLightsDrawn = 0, pointLightsCulled = 0;
    };
    const FrameStats& getFrameStats() const { return frameStats; }
    // The targets the renderer owns: the G-buffer's three and the light map.
    std::vector<const RenderTarget2D*> getTargets() const;

    // fxport: the passes Draw runs, public (private in the seed) so that the render tests can run
    // the shipped renderer one pass at a time on inputs they upload into its targets (getGBuffer(),
    // getLightMap()) and read each pass's target back (tests/render/deferred_passes_test.cpp).
    //Clear GBuffer
    void ClearGBuffer(GraphicsDevice& GraphicsDevice);
    //GBuffer Creation
    void MakeGBuffer(GraphicsDevice& GraphicsDevice, const std::vector<Model*>& Models, BaseCamera& Camera);
    //Light Map Creation
    void MakeLightMap(GraphicsDevice& GraphicsDevice, Lights::LightManager& Lights, BaseCamera& Camera);
    //Composition
    void MakeFinal(GraphicsDevice& GraphicsDevice, RenderTarget2D* Output);

private:

    // fxport: C# keeps the G-buffer targets alive through GBufferTargets (garbage collection);
    // here they are owned here and GBufferTargets points at them.
    std::vector<std::unique_ptr<RenderTarget2D>> GBufferTargetsOwned;
    GpuTimer* gpuTimer = nullptr;
    ContentManager& content;
    FrameStats frameStats;
    // Load on first use (see the light shaders above).
    Effect* LoadEffect(const char* assetName);
    Model& SpotLightGeometry();
    Model& PointLightGeometry();
};

}  // namespace TheCansinDeferredRenderer
