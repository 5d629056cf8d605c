#include "deferred/ssao.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace TheCansinDeferredRenderer {

namespace {

// C#'s float.ToString() (.NET Framework, as XNA ran on: up to 7 significant digits).
std::string ToString(float value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.7g", double(value));
    return text;
}

}  // namespace

//Constructor
SSAO::SSAO(GraphicsDevice& GraphicsDevice, ContentManager& Content, int Width, int Height) {
    //Load SSAO effect
    ssao = Content.Load<Effect>("Effects/SSAO");
    ssao->CurrentTechnique = ssao->Techniques[0];

    //Load SSAO Blur effect
    ssaoBlur = Content.Load<Effect>("Effects/SSAOBlur");
    ssaoBlur->CurrentTechnique = ssaoBlur->Techniques[0];

    //Load SSAO composition effect
    composer = Content.Load<Effect>("Effects/SSAOFinal");
    composer->CurrentTechnique = composer->Techniques[0];

    //Create SSAO Target
    SSAOTarget = std::make_unique<RenderTarget2D>(GraphicsDevice, Width, Height, false, SurfaceFormat::Color,
                                                  DepthFormat::None);
    SSAOTarget->Name = "SSAOTarget";

    //Create SSAO Blur Target
    BlurTarget = std::make_unique<RenderTarget2D>(GraphicsDevice, Width, Height, false, SurfaceFormat::Color,
                                                  DepthFormat::None);
    BlurTarget->Name = "BlurTarget";

    //Create FSQ
    fsq = std::make_unique<FullscreenQuad>(GraphicsDevice);

    //Load Random Normal Texture
    randomNormals = Content.Load<Texture2D>("RandomNormals");

    //Set Sample Radius to Default
    sampleRadius = 0;

    //Set Distance Scale to Default
    distanceScale = 0;
}

//Draw
// Reconstructed: seed 000 is cut here (the text announces "add a Draw function to the SSAO class"
// and says what it does: "draw the SSAO, blur that SSAO and then combine it with the Scene image";
// the signature is the one Game1 calls: ssao.Draw(GraphicsDevice, deferredRenderer.getGBuffer(),
// Scene, Camera, null); the states are the ones every Draw of the tutorial starts with).
void SSAO::Draw(GraphicsDevice& GraphicsDevice, const std::vector<RenderTargetBinding>& GBuffer, RenderTarget2D* Scene,
                BaseCamera& Camera, RenderTarget2D* Output) {
    //Set States
    GraphicsDevice.BlendState = BlendState::Opaque;
    GraphicsDevice.DepthStencilState = DepthStencilState::Default;
    GraphicsDevice.RasterizerState = RasterizerState::CullCounterClockwise;

    //Render SSAO
    { PassTimer timed(gpuTimer, "SSAO"); RenderSSAO(GraphicsDevice, GBuffer, Camera); }

    //Blur SSAO
    { PassTimer timed(gpuTimer, "SSAOBlur"); BlurSSAO(GraphicsDevice); }

    //Compose final
    { PassTimer timed(gpuTimer, "SSAOFinal"); Compose(GraphicsDevice, Scene, Output, true); }
}

//Render SSAO
// Reconstructed: seed 000 is cut here ("So now we define the RenderSSAO method, which will pretty
// much just interface with the SSAO shader as a fullscreen post-process:" is followed by no code).
// Written from SSAO.fx's inputs: GBuffer1 (normals) at s1, GBuffer2 (depth) at s2, RandNormal at s3
// sampled at UV * 200 (so wrapping), Projection, cornerFustrum (the view-space corner of the far
// plane, as the vertex shader builds ViewDirection from it), sampleRadius, distanceScale and
// GBufferTextureSize; in the style of BlurSSAO and Compose.
void SSAO::RenderSSAO(GraphicsDevice& GraphicsDevice, const std::vector<RenderTargetBinding>& GBuffer,
                      BaseCamera& Camera) {
    //Set SSAO Target
    GraphicsDevice.SetRenderTarget(SSAOTarget.get());

    //Clear
    GraphicsDevice.Clear(Color::White);
    // fxport (issue 16): the full-screen quad below writes every pixel, opaque, and SSAO.fx never
    // discards, so the clear is never seen: the device drops it (D3D11.1's DiscardView;
    // FXPORT_HONOUR_DISCARDS=0 keeps it). The same image. Likewise in BlurSSAO and Compose.
    GraphicsDevice.DiscardContents(ClearOptions::Target);

    //Set Samplers
    GraphicsDevice.Textures[1] = GBuffer[1].RenderTarget;
    GraphicsDevice.SamplerStates[1] = SamplerState::LinearClamp;
    GraphicsDevice.Textures[2] = GBuffer[2].RenderTarget;
    GraphicsDevice.SamplerStates[2] = SamplerState::PointClamp;
    GraphicsDevice.Textures[3] = randomNormals;
    GraphicsDevice.SamplerStates[3] = SamplerState::LinearWrap;

    //Calculate the Corner of the Frustum at the Far Plane
    Vector3 cornerFrustum = Vector3::Zero;
    cornerFrustum.Y = float(std::tan(double(Camera.FieldOfView) / 2.0)) * Camera.FarPlane;
    cornerFrustum.X = cornerFrustum.Y * Camera.AspectRatio;
    cornerFrustum.Z = Camera.FarPlane;

    //Set SSAO parameters
    ssao->Parameters["Projection"].SetValue(Camera.Projection);
    ssao->Parameters["cornerFustrum"].SetValue(cornerFrustum);
    ssao->Parameters["sampleRadius"].SetValue(sampleRadius);
    ssao->Parameters["distanceScale"].SetValue(distanceScale);
    ssao->Parameters["GBufferTextureSize"].SetValue(Vector2(float(SSAOTarget->Width()), float(SSAOTarget->Height())));

    //Apply
    ssao->CurrentTechnique->Passes[0].Apply();

    //Draw
    fsq->Draw(GraphicsDevice);
}

//Blur SSAO
void SSAO::BlurSSAO(GraphicsDevice& GraphicsDevice) {
    //Set Blur Target
    GraphicsDevice.SetRenderTarget(BlurTarget.get());

    //Clear
    GraphicsDevice.Clear(Color::White);
    GraphicsDevice.DiscardContents(ClearOptions::Target);  // fxport: see RenderSSAO

    //Set Samplers, GBuffer was set before so no need to reset...
    GraphicsDevice.Textures[3] = SSAOTarget;
    // Reconstructed: seed 000 is cut here (the listing stops after Textures[3]; the rest follows
    // SSAOBlur.fx's parameters - blurDirection, one step in UV units, here one texel diagonally, and
    // targetSize - and the other fullscreen passes).
    GraphicsDevice.SamplerStates[3] = SamplerState::LinearClamp;

    //Set Blur parameters
    ssaoBlur->Parameters["blurDirection"].SetValue(
        Vector2(1.0f / float(SSAOTarget->Width()), 1.0f / float(SSAOTarget->Height())));
    ssaoBlur->Parameters["targetSize"].SetValue(Vector2(float(SSAOTarget->Width()), float(SSAOTarget->Height())));

    //Apply
    ssaoBlur->CurrentTechnique->Passes[0].Apply();

    //Draw
    fsq->Draw(GraphicsDevice);
}

//Compose
void SSAO::Compose(GraphicsDevice& GraphicsDevice, RenderTarget2D* Scene, RenderTarget2D* Output, bool useBlurredSSAO) {
    //Set Output Target
    GraphicsDevice.SetRenderTarget(Output);

    //Clear
    GraphicsDevice.Clear(Color::White);
    GraphicsDevice.DiscardContents(ClearOptions::Target);  // fxport: see RenderSSAO

    //Set Samplers
    GraphicsDevice.Textures[0] = Scene;
    GraphicsDevice.SamplerStates[0] = SamplerState::LinearClamp;
    if (useBlurredSSAO) GraphicsDevice.Textures[1] = BlurTarget;
    else GraphicsDevice.Textures[1] = SSAOTarget;
    GraphicsDevice.SamplerStates[1] = SamplerState::LinearClamp;

    //Set Effect Parameters
    // fxport: one texel of the image drawn (the Scene's size, as the output has it); the seed's
    // SSAO target has that size too unless DemoSettings::ssaoHalfResolution halves it.
    composer->Parameters["halfPixel"].SetValue(Vector2(1.0f / float(Scene->Width()), 1.0f / float(Scene->Height())));
    composer->CurrentTechnique->Passes[0].Apply();

    //Draw
    fsq->Draw(GraphicsDevice);
}

//Modify
void SSAO::Modify(const KeyboardState& Current) {
    float speed = 0.01f;
    if (Current.IsKeyDown(Keys::Z)) sampleRadius -= speed;
    if (Current.IsKeyDown(Keys::X)) sampleRadius += speed;
    if (Current.IsKeyDown(Keys::C)) distanceScale -= speed;
    if (Current.IsKeyDown(Keys::V)) distanceScale += speed;
}

//Debug Values
void SSAO::Debug(SpriteBatch& spriteBatch, SpriteFont& spriteFont) {
    //Width + Height
    int width = 128;
    int height = 128;

    //Set up Drawing Rectangle
    Rectangle rect = Rectangle(384, 0, width, height);

    //Begin SpriteBatch for Buffer
    spriteBatch.Begin(SpriteSortMode::Immediate, BlendState::Opaque, SamplerState::LinearClamp, nullptr, nullptr);

    //Draw SSAO buffer
    spriteBatch.Draw(*SSAOTarget, rect, Color::White);

    //Draw SSAO Blurred
    rect.X += 128;
    spriteBatch.Draw(*BlurTarget, rect, Color::White);

    //End SpriteBatch
    spriteBatch.End();

    //Begin SpriteBatch for Text
    spriteBatch.Begin(SpriteSortMode::Immediate, BlendState::AlphaBlend);

    //Draw sampleRadius
    spriteBatch.DrawString(spriteFont, "Sample Radius: " + ToString(sampleRadius), Vector2(0, 128), Color::Red);

    //Draw distanceScale
    spriteBatch.DrawString(spriteFont, "Distance Scale: " + ToString(distanceScale), Vector2(0, 148), Color::Blue);

    //End SpriteBatch
    spriteBatch.End();
}

}  // namespace TheCansinDeferredRenderer
