// DeferredRenderer (seed 000, chapters 2-5, in its final form): clears and fills the G-buffer,
// accumulates the lights into the light map and composes the lit scene.
#pragma once

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
    //Directional Light Shader
    Effect* directionalLight;
    //Point Light Shader
    Effect* pointLight;
    //Spot Light Shader
    Effect* spotLight;
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
    Model* pointLightGeometry;
    //Spot Light Geometry
    Model* spotLightGeometry;

public:
    //Get GBuffer
    const std::vector<RenderTargetBinding>& getGBuffer() const { return GBufferTargets; }
    //Constructor
    DeferredRenderer(GraphicsDevice& GraphicsDevice, ContentManager& Content, int Width, int Height);

    //Draw Scene Deferred
    void Draw(GraphicsDevice& GraphicsDevice, const std::vector<Model*>& Models, Lights::LightManager& Lights,
              BaseCamera& Camera, RenderTarget2D* Output);
    //Debug
    void Debug(GraphicsDevice& GraphicsDevice, SpriteBatch& spriteBatch);

    // fxport additions: the light map for fxdemo's debug sheet, and a GPU timer for the passes.
    RenderTarget2D& getLightMap() const { return *LightMap; }
    void setGpuTimer(GpuTimer* timer) { gpuTimer = timer; }

private:
    //Clear GBuffer
    void ClearGBuffer(GraphicsDevice& GraphicsDevice);
    //GBuffer Creation
    void MakeGBuffer(GraphicsDevice& GraphicsDevice, const std::vector<Model*>& Models, BaseCamera& Camera);
    //Light Map Creation
    void MakeLightMap(GraphicsDevice& GraphicsDevice, Lights::LightManager& Lights, BaseCamera& Camera);
    //Composition
    void MakeFinal(GraphicsDevice& GraphicsDevice, RenderTarget2D* Output);

    // fxport: C# keeps the G-buffer targets alive through GBufferTargets (garbage collection);
    // here they are owned here and GBufferTargets points at them.
    std::vector<std::unique_ptr<RenderTarget2D>> GBufferTargetsOwned;
    GpuTimer* gpuTimer = nullptr;
};

}  // namespace TheCansinDeferredRenderer
