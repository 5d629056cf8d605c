// SSAO (seed 000, chapter 6): screen-space ambient occlusion from the G-buffer's view-space depth
// and normals, a bilateral blur, and the composition with the lit scene.
#pragma once

#include <memory>
#include <vector>

#include "deferred/Cameras/base_camera.h"
#include "deferred/xna.h"

namespace TheCansinDeferredRenderer {

class SSAO {
    //SSAO effect
    Effect* ssao;

    //SSAO Blur Effect
    Effect* ssaoBlur;

    //SSAO Composition effect
    Effect* composer;

    //Random Normal Texture
    Texture2D* randomNormals;

    //Sample Radius
    float sampleRadius;

    //Distance Scale
    float distanceScale;

    //SSAO Target
    std::unique_ptr<RenderTarget2D> SSAOTarget;

    //Blue Target
    std::unique_ptr<RenderTarget2D> BlurTarget;

    //FSQ
    std::unique_ptr<FullscreenQuad> fsq;

public:
    // #region Get Methods
    //Get Sample Radius
    float getSampleRadius() const { return sampleRadius; }

    //Get Distance Scale
    float getDistanceScale() const { return distanceScale; }
    // #endregion

    // #region Set Methods
    // fxport: public (private in the seed), so that fxdemo can start a headless run with the values
    // a player would reach by holding Z/X/C/V; the seed starts both at 0, where SSAO is all white.
    //Set Sample Radius
    void setSampleRadius(float radius) { this->sampleRadius = radius; }

    //Set Distance Scale
    void setDistanceScale(float scale) { this->distanceScale = scale; }
    // #endregion

    //Constructor
    SSAO(GraphicsDevice& GraphicsDevice, ContentManager& Content, int Width, int Height);

    //Draw
    void Draw(GraphicsDevice& GraphicsDevice, const std::vector<RenderTargetBinding>& GBuffer, RenderTarget2D* Scene,
              BaseCamera& Camera, RenderTarget2D* Output);

    //Modify
    void Modify(const KeyboardState& Current);

    //Debug Values
    void Debug(SpriteBatch& spriteBatch, SpriteFont& spriteFont);

    // fxport additions: the targets for fxdemo's debug sheet, and a GPU timer for the passes.
    RenderTarget2D& getSSAOTarget() const { return *SSAOTarget; }
    RenderTarget2D& getBlurTarget() const { return *BlurTarget; }
    void setGpuTimer(GpuTimer* timer) { gpuTimer = timer; }
    // fxport: the random-normal texture RenderSSAO samples (the content's RandomNormals), settable so
    // that the render tests' end-to-end frame runs the shipped RenderSSAO on their own texture
    // (tests/render/deferred_pipeline_test.cpp says why).
    Texture2D& getRandomNormals() const { return *randomNormals; }
    void setRandomNormals(Texture2D& texture) { randomNormals = &texture; }

    // fxport: SSAO's passes, public (private in the seed) for the render tests, as DeferredRenderer's.
    //Render SSAO
    void RenderSSAO(GraphicsDevice& GraphicsDevice, const std::vector<RenderTargetBinding>& GBuffer,
                    BaseCamera& Camera);

    //Blur SSAO
    void BlurSSAO(GraphicsDevice& GraphicsDevice);

    //Compose
    void Compose(GraphicsDevice& GraphicsDevice, RenderTarget2D* Scene, RenderTarget2D* Output, bool useBlurredSSAO);

private:

    GpuTimer* gpuTimer = nullptr;
};

}  // namespace TheCansinDeferredRenderer
