#include "deferred/deferred_renderer.h"

#include <algorithm>
#include <cmath>

namespace TheCansinDeferredRenderer {

//Constructor
DeferredRenderer::DeferredRenderer(GraphicsDevice& GraphicsDevice, ContentManager& Content, int Width, int Height,
                                   std::array<SurfaceFormat, 3> GBufferFormats)
    : content(Content) {
    //Load Clear Shader
    Clear = Content.Load<Effect>("Effects/Clear");
    Clear->CurrentTechnique = Clear->Techniques[0];
    //Load GBuffer Shader
    GBuffer = Content.Load<Effect>("Effects/GBuffer");
    GBuffer->CurrentTechnique = GBuffer->Techniques[0];
    //Load Directional Light Shader
    //Load Point Light Shader
    //Load Spot Light Shader
    // fxport: each with the first light of its type (MakeLightMap).
    //Load Composition Shader
    compose = Content.Load<Effect>("Effects/Composition");
    compose->CurrentTechnique = compose->Techniques[0];
    //Create LightMap BlendState
    LightMapBS = BlendState();
    LightMapBS.ColorSourceBlend = Blend::One;
    LightMapBS.ColorDestinationBlend = Blend::One;
    LightMapBS.ColorBlendFunction = BlendFunction::Add;
    LightMapBS.AlphaSourceBlend = Blend::One;
    LightMapBS.AlphaDestinationBlend = Blend::One;
    LightMapBS.AlphaBlendFunction = BlendFunction::Add;
    //Set GBuffer Texture Size
    GBufferTextureSize = Vector2(float(Width), float(Height));
    //Initialize GBuffer Targets Array
    GBufferTargets = std::vector<RenderTargetBinding>(3);
    //Intialize Each Target of the GBuffer
    GBufferTargetsOwned.push_back(std::make_unique<RenderTarget2D>(GraphicsDevice, Width, Height, false,
                                                                   GBufferFormats[0], DepthFormat::Depth24Stencil8));
    GBufferTargets[0] = RenderTargetBinding(GBufferTargetsOwned.back().get());
    GBufferTargetsOwned.push_back(std::make_unique<RenderTarget2D>(GraphicsDevice, Width, Height, false,
                                                                   GBufferFormats[1], DepthFormat::Depth24Stencil8));
    GBufferTargets[1] = RenderTargetBinding(GBufferTargetsOwned.back().get());
    GBufferTargetsOwned.push_back(std::make_unique<RenderTarget2D>(GraphicsDevice, Width, Height, false,
                                                                   GBufferFormats[2], DepthFormat::Depth24Stencil8));
    GBufferTargets[2] = RenderTargetBinding(GBufferTargetsOwned.back().get());
    GBufferTargetsOwned[0]->Name = "GBuffer0";
    GBufferTargetsOwned[1]->Name = "GBuffer1";
    GBufferTargetsOwned[2]->Name = "GBuffer2";
    //Initialize LightMap
    LightMap = std::make_unique<RenderTarget2D>(GraphicsDevice, Width, Height, false, SurfaceFormat::Color,
                                                DepthFormat::Depth24Stencil8);
    LightMap->Name = "LightMap";
    //Create Fullscreen Quad
    fsq = std::make_unique<FullscreenQuad>(GraphicsDevice);
    //Load Point Light Geometry
    //Load Spot Light Geometry
    // fxport: each with the first light of its type (PointLightGeometry(), SpotLightGeometry()).
}

Effect* DeferredRenderer::LoadEffect(const char* assetName) {
    Effect* effect = content.Load<Effect>(assetName);
    effect->CurrentTechnique = effect->Techniques[0];
    return effect;
}

Model& DeferredRenderer::SpotLightGeometry() {
    if (!spotLightGeometry) spotLightGeometry = content.Load<Model>("SpotLightGeometry");
    return *spotLightGeometry;
}

Model& DeferredRenderer::PointLightGeometry() {
    if (!pointLightGeometry) pointLightGeometry = content.Load<Model>("PointLightGeometry");
    return *pointLightGeometry;
}

// fxport: the spot light's volume is SpotLightGeometry (a cone, apex at the origin, axis -Z, length
// 1, base radius 0.5; its vertices lie on that cone, so the mesh is inside it) under the light's
// World. The cone is outside the frustum when it is wholly outside one plane (normals point out):
// both its apex and the nearest point of its base disk lie outside. The mesh's bounding sphere was
// tested before: for a cone 100 long it is 100 across and almost never outside a plane.
bool DeferredRenderer::IsVisible(const Lights::SpotLight& light, const BaseCamera& Camera) {
    if (!frustumCulling) return true;
    const Matrix world = light.getWorld();
    const Vector3 apex = Vector3::Transform(Vector3(0, 0, 0), world);
    const Vector3 baseCentre = Vector3::Transform(Vector3(0, 0, -1), world);
    const float baseRadius = (Vector3::Transform(Vector3(0.5f, 0, -1), world) - baseCentre).Length();
    const Vector3 axis = Vector3::Normalize(baseCentre - apex);
    const BoundingFrustum frustum(Camera.View * Camera.Projection);
    for (const Plane* plane : {&frustum.Near(), &frustum.Far(), &frustum.Left(), &frustum.Right(), &frustum.Top(),
                               &frustum.Bottom()}) {
        // The base disk's nearest point to the plane is its centre moved by the radius along the
        // plane's normal with the axis component taken out: |n - (n.a) a| = sqrt(1 - (n.a)^2).
        const float along = Vector3::Dot(plane->Normal, axis);
        const float diskNearest = plane->DotCoordinate(baseCentre) - baseRadius * std::sqrt(std::max(0.0f, 1 - along * along));
        if (plane->DotCoordinate(apex) > 0 && diskNearest > 0) return false;
    }
    return true;
}

bool DeferredRenderer::IsVisible(const Lights::PointLight& light, const BaseCamera& Camera) {
    if (!frustumCulling) return true;
    const BoundingSphere volume = PointLightGeometry().Meshes[0].BoundingSphere.Transform(light.World());
    return BoundingFrustum(Camera.View * Camera.Projection).Intersects(volume);
}

std::vector<const RenderTarget2D*> DeferredRenderer::getTargets() const {
    std::vector<const RenderTarget2D*> targets;
    for (auto& target : GBufferTargetsOwned) targets.push_back(target.get());
    targets.push_back(LightMap.get());
    return targets;
}

//Draw Scene Deferred
// Reconstructed: seed 000 is cut here (chapter 2 shows Draw with the states, ClearGBuffer and
// MakeGBuffer; chapter 3 shows only its last two calls, MakeLightMap and MakeFinal, and the closing
// brace; the signature is the one Game1 calls: Draw(GraphicsDevice, models, lightManager, Camera,
// Scene or null)).
void DeferredRenderer::Draw(GraphicsDevice& GraphicsDevice, const std::vector<Model*>& Models,
                            Lights::LightManager& Lights, BaseCamera& Camera, RenderTarget2D* Output) {
    //Set States
    GraphicsDevice.BlendState = BlendState::Opaque;
    GraphicsDevice.DepthStencilState = DepthStencilState::Default;
    GraphicsDevice.RasterizerState = RasterizerState::CullCounterClockwise;

    //Clear GBuffer
    { PassTimer timed(gpuTimer, "ClearGBuffer"); ClearGBuffer(GraphicsDevice); }

    //Make GBuffer
    { PassTimer timed(gpuTimer, "GBuffer"); MakeGBuffer(GraphicsDevice, Models, Camera); }

    //Make LightMap
    { PassTimer timed(gpuTimer, "LightMap"); MakeLightMap(GraphicsDevice, Lights, Camera); }

    //Make Final Rendered Scene
    { PassTimer timed(gpuTimer, "Composition"); MakeFinal(GraphicsDevice, Output); }
}

//Clear GBuffer
void DeferredRenderer::ClearGBuffer(GraphicsDevice& GraphicsDevice) {
    //Set to ReadOnly depth for now...
    GraphicsDevice.DepthStencilState = DepthStencilState::DepthRead;

    //Set GBuffer Render Targets
    GraphicsDevice.SetRenderTargets(GBufferTargets);
    // (The G-buffer's depth is cleared by SetRenderTargets: the targets are DiscardContents, which
    // XNA 4 -- and fxport -- clears when set.)

    // fxport (issue 16): Clear.fx's quad writes every pixel of the three targets with blending
    // off, so the colour SetRenderTargets cleared them to is never seen: the device drops that
    // clear (D3D11.1's DiscardView; FXPORT_HONOUR_DISCARDS=0 keeps it). The same image.
    GraphicsDevice.DiscardContents(ClearOptions::Target);

    //Set Clear Effect
    Clear->CurrentTechnique->Passes[0].Apply();

    //Draw
    fsq->Draw(GraphicsDevice);
}

//GBuffer Creation
void DeferredRenderer::MakeGBuffer(GraphicsDevice& GraphicsDevice, const std::vector<Model*>& Models,
                                   BaseCamera& Camera) {
    //Set Depth State
    GraphicsDevice.DepthStencilState = DepthStencilState::Default;

    //Set up global GBuffer parameters
    GBuffer->Parameters["View"].SetValue(Camera.View);
    GBuffer->Parameters["Projection"].SetValue(Camera.Projection);

    //Draw Each Model
    for (Model* model : Models) {
        //Get Transforms
        std::vector<Matrix> transforms(std::size_t(model->Bones.Count()));
        model->CopyAbsoluteBoneTransformsTo(transforms);

        //Draw Each ModelMesh
        for (ModelMesh& mesh : model->Meshes) {
            //Draw Each ModelMeshPart
            for (ModelMeshPart& part : mesh.MeshParts) {
                //Set Vertex Buffer
                GraphicsDevice.SetVertexBuffer(part.VertexBuffer, part.VertexOffset);

                //Set Index Buffer
                GraphicsDevice.Indices = part.IndexBuffer;

                //Set World
                GBuffer->Parameters["World"].SetValue(transforms[std::size_t(mesh.ParentBone->Index)]);

                //Set WorldIT
                GBuffer->Parameters["WorldViewIT"].SetValue(
                    Matrix::Transpose(Matrix::Invert(transforms[std::size_t(mesh.ParentBone->Index)] * Camera.View)));

                //Set Albedo Texture
                GBuffer->Parameters["Texture"].SetValue(part.Effect->Parameters["Texture"].GetValueTexture2D());

                //Set Normal Texture
                // fxport: the part's default effect is XNA's BasicEffect, which has no normal or
                // specular map (the tutorial's content processor stored them in the effect); the
                // glTF material's maps are kept in part.Textures.
                GBuffer->Parameters["NormalMap"].SetValue(part.Textures.NormalMap);

                //Set Specular Texture
                GBuffer->Parameters["SpecularMap"].SetValue(part.Textures.SpecularMap);

                //Apply Effect
                GBuffer->CurrentTechnique->Passes[0].Apply();

                // Reconstructed: seed 000 is cut here (the listing stops after Apply(); the draw is the
                // one of the light volumes in MakeLightMap, with the part's counts).
                //Draw
                GraphicsDevice.DrawIndexedPrimitives(PrimitiveType::TriangleList, 0, 0, part.NumVertices,
                                                     part.StartIndex, part.PrimitiveCount);
            }
        }
    }
}

//Light Map Creation
void DeferredRenderer::MakeLightMap(GraphicsDevice& GraphicsDevice, Lights::LightManager& Lights, BaseCamera& Camera) {
    //Set LightMap Target
    GraphicsDevice.SetRenderTarget(LightMap.get());

    //Clear to Transperant Black
    GraphicsDevice.Clear(Color::Transparent);

    //Set States
    GraphicsDevice.BlendState = LightMapBS;
    GraphicsDevice.DepthStencilState = DepthStencilState::DepthRead;

    // #region Set Global Samplers
    //GBuffer 1 Sampler
    GraphicsDevice.Textures[0] = GBufferTargets[0].RenderTarget;
    GraphicsDevice.SamplerStates[0] = SamplerState::LinearClamp;

    //GBuffer 2 Sampler
    GraphicsDevice.Textures[1] = GBufferTargets[1].RenderTarget;
    GraphicsDevice.SamplerStates[1] = SamplerState::LinearClamp;

    //GBuffer 3 Sampler
    GraphicsDevice.Textures[2] = GBufferTargets[2].RenderTarget;
    GraphicsDevice.SamplerStates[2] = SamplerState::PointClamp;

    //SpotLight Cookie Sampler
    GraphicsDevice.SamplerStates[3] = SamplerState::LinearClamp;

    //ShadowMap Sampler
    GraphicsDevice.SamplerStates[4] = SamplerState::PointClamp;
    // #endregion

    //Calculate InverseView
    Matrix InverseView = Matrix::Invert(Camera.View);

    //Calculate InverseViewProjection
    Matrix InverseViewProjection = Matrix::Invert(Camera.View * Camera.Projection);

    // fxport: what this frame draws (see FrameStats); a light type the scene lacks loads nothing
    // and sets nothing; a spot or point light whose volume is outside the frustum is not drawn.
    frameStats = FrameStats();

    if (!Lights.getDirectionalLights().empty()) {
        if (!directionalLight) directionalLight = LoadEffect("Effects/DirectionalLight");
        //Set Directional Lights Globals
        directionalLight->Parameters["InverseViewProjection"].SetValue(InverseViewProjection);
        directionalLight->Parameters["inverseView"].SetValue(InverseView);
        directionalLight->Parameters["CameraPosition"].SetValue(Camera.Position);
        directionalLight->Parameters["GBufferTextureSize"].SetValue(GBufferTextureSize);

        //Set the Directional Lights Geometry Buffers
        fsq->ReadyBuffers(GraphicsDevice);

        //Draw Directional Lights
        for (auto& light : Lights.getDirectionalLights()) {
            //Set Directional Light Parameters
            directionalLight->Parameters["L"].SetValue(Vector3::Normalize(light->getDirection()));
            directionalLight->Parameters["LightColor"].SetValue(light->getColor());
            directionalLight->Parameters["LightIntensity"].SetValue(light->getIntensity());

            //Apply
            directionalLight->CurrentTechnique->Passes[0].Apply();

            //Draw
            fsq->JustDraw(GraphicsDevice);
            ++frameStats.directionalLightsDrawn;
        }
    }

    if (!Lights.getSpotLights().empty()) {
        if (!spotLight) spotLight = LoadEffect("Effects/SpotLight");
        Model& spotLightGeometry = SpotLightGeometry();
        //Set Spot Lights Globals
        spotLight->Parameters["View"].SetValue(Camera.View);
        spotLight->Parameters["inverseView"].SetValue(InverseView);
        spotLight->Parameters["Projection"].SetValue(Camera.Projection);
        spotLight->Parameters["InverseViewProjection"].SetValue(InverseViewProjection);
        spotLight->Parameters["CameraPosition"].SetValue(Camera.Position);
        spotLight->Parameters["GBufferTextureSize"].SetValue(GBufferTextureSize);

        //Set Spot Lights Geometry Buffers
        GraphicsDevice.SetVertexBuffer(spotLightGeometry.Meshes[0].MeshParts[0].VertexBuffer,
                                       spotLightGeometry.Meshes[0].MeshParts[0].VertexOffset);
        GraphicsDevice.Indices = spotLightGeometry.Meshes[0].MeshParts[0].IndexBuffer;

        //Draw Spot Lights
        for (auto& light : Lights.getSpotLights()) {
            // fxport: frustum culling.
            if (!IsVisible(*light, Camera)) {
                ++frameStats.spotLightsCulled;
                continue;
            }

            //Set Attenuation Cookie Texture and SamplerState
            GraphicsDevice.Textures[3] = light->getAttenuationTexture();

            //Set ShadowMap and SamplerState
            GraphicsDevice.Textures[4] = light->getShadowMap();

            //Set Spot Light Parameters
            spotLight->Parameters["World"].SetValue(light->getWorld());
            spotLight->Parameters["LightViewProjection"].SetValue(light->getView() * light->getProjection());
            spotLight->Parameters["LightPosition"].SetValue(light->getPosition());
            spotLight->Parameters["LightColor"].SetValue(light->getColor());
            spotLight->Parameters["LightIntensity"].SetValue(light->getIntensity());
            spotLight->Parameters["S"].SetValue(light->getDirection());
            spotLight->Parameters["LightAngleCos"].SetValue(light->LightAngleCos());
            spotLight->Parameters["LightHeight"].SetValue(light->getFarPlane());
            spotLight->Parameters["Shadows"].SetValue(light->getIsWithShadows());
            spotLight->Parameters["shadowMapSize"].SetValue(light->getShadowMapResoloution());
            spotLight->Parameters["DepthPrecision"].SetValue(light->getFarPlane());
            spotLight->Parameters["DepthBias"].SetValue(light->getDepthBias());

            // #region Set Cull Mode
            //Calculate L
            Vector3 L = Camera.Position - light->getPosition();

            //Calculate S.L
            float SL = std::fabs(Vector3::Dot(L, light->getDirection()));

            //Check if SL is within the LightAngle, if so then draw the BackFaces, if not
            //then draw the FrontFaces
            if (SL < light->LightAngleCos())
                GraphicsDevice.RasterizerState = RasterizerState::CullCounterClockwise;
            else
                GraphicsDevice.RasterizerState = RasterizerState::CullClockwise;
            // #endregion

            //Apply
            spotLight->CurrentTechnique->Passes[0].Apply();

            //Draw
            GraphicsDevice.DrawIndexedPrimitives(PrimitiveType::TriangleList, 0, 0,
                                                 spotLightGeometry.Meshes[0].MeshParts[0].NumVertices,
                                                 spotLightGeometry.Meshes[0].MeshParts[0].StartIndex,
                                                 spotLightGeometry.Meshes[0].MeshParts[0].PrimitiveCount);
            ++frameStats.spotLightsDrawn;
        }
    }

    if (!Lights.getPointLights().empty()) {
        if (!pointLight) pointLight = LoadEffect("Effects/PointLight");
        Model& pointLightGeometry = PointLightGeometry();
        //Set Point Lights Geometry Buffers
        GraphicsDevice.SetVertexBuffer(pointLightGeometry.Meshes[0].MeshParts[0].VertexBuffer,
                                       pointLightGeometry.Meshes[0].MeshParts[0].VertexOffset);
        GraphicsDevice.Indices = pointLightGeometry.Meshes[0].MeshParts[0].IndexBuffer;

        //Set Point Lights Globals
        pointLight->Parameters["inverseView"].SetValue(InverseView);
        pointLight->Parameters["View"].SetValue(Camera.View);
        pointLight->Parameters["Projection"].SetValue(Camera.Projection);
        pointLight->Parameters["InverseViewProjection"].SetValue(InverseViewProjection);
        pointLight->Parameters["CameraPosition"].SetValue(Camera.Position);
        pointLight->Parameters["GBufferTextureSize"].SetValue(GBufferTextureSize);

        //Draw Point Lights without Shadows
        for (auto& light : Lights.getPointLights()) {
            // fxport: frustum culling.
            if (!IsVisible(*light, Camera)) {
                ++frameStats.pointLightsCulled;
                continue;
            }

            //Set Point Light Sampler
            GraphicsDevice.Textures[4] = light->getShadowMap();
            GraphicsDevice.SamplerStates[4] = SamplerState::PointWrap;

            //Set Point Light Parameters
            pointLight->Parameters["World"].SetValue(light->World());
            pointLight->Parameters["LightPosition"].SetValue(light->getPosition());
            pointLight->Parameters["LightRadius"].SetValue(light->getRadius());
            pointLight->Parameters["LightColor"].SetValue(light->getColor());
            pointLight->Parameters["LightIntensity"].SetValue(light->getIntensity());
            pointLight->Parameters["Shadows"].SetValue(light->getIsWithShadows());
            pointLight->Parameters["DepthPrecision"].SetValue(light->getRadius());
            pointLight->Parameters["DepthBias"].SetValue(light->getDepthBias());
            pointLight->Parameters["shadowMapSize"].SetValue(light->getShadowMapResoloution());

            //Set Cull Mode
            Vector3 diff = Camera.Position - light->getPosition();
            float CameraToLight = float(std::sqrt(float(Vector3::Dot(diff, diff)))) / 100.0f;

            //If the Camera is in the light, render the backfaces, if it's out of the
            //light, render the frontfaces
            if (CameraToLight <= light->getRadius())
                GraphicsDevice.RasterizerState = RasterizerState::CullClockwise;
            else if (CameraToLight > light->getRadius())
                GraphicsDevice.RasterizerState = RasterizerState::CullCounterClockwise;

            //Apply
            pointLight->CurrentTechnique->Passes[0].Apply();

            //Draw
            GraphicsDevice.DrawIndexedPrimitives(PrimitiveType::TriangleList, 0, 0,
                                                 pointLightGeometry.Meshes[0].MeshParts[0].NumVertices,
                                                 pointLightGeometry.Meshes[0].MeshParts[0].StartIndex,
                                                 pointLightGeometry.Meshes[0].MeshParts[0].PrimitiveCount);
            ++frameStats.pointLightsDrawn;
        }
    }

    //Set States Off
    GraphicsDevice.BlendState = BlendState::Opaque;
    GraphicsDevice.RasterizerState = RasterizerState::CullCounterClockwise;
    GraphicsDevice.DepthStencilState = DepthStencilState::Default;
}

//Composition
void DeferredRenderer::MakeFinal(GraphicsDevice& GraphicsDevice, RenderTarget2D* Output) {
    //Set Composition Target
    GraphicsDevice.SetRenderTarget(Output);

    //Clear
    GraphicsDevice.Clear(Color::Transparent);
    GraphicsDevice.DiscardContents(ClearOptions::Target);  // fxport: the quad below covers it (see ClearGBuffer)

    //Set Textures
    GraphicsDevice.Textures[0] = GBufferTargets[0].RenderTarget;
    GraphicsDevice.SamplerStates[0] = SamplerState::LinearClamp;
    GraphicsDevice.Textures[1] = LightMap;
    GraphicsDevice.SamplerStates[1] = SamplerState::LinearClamp;

    //Set Effect Parameters
    compose->Parameters["GBufferTextureSize"].SetValue(GBufferTextureSize);

    //Apply
    compose->CurrentTechnique->Passes[0].Apply();

    //Draw
    fsq->Draw(GraphicsDevice);
}

//Debug
void DeferredRenderer::Debug(GraphicsDevice& GraphicsDevice, SpriteBatch& spriteBatch) {
    (void)GraphicsDevice;
    // Reconstructed: seed 000 is cut here (the listing starts at "//Width + Height"; the signature
    // is the one Game1 calls, and the Begin follows the text: "you have to use Point sampling as in
    // XNA4 you can't Linear sample vector targets", in the form SSAO.Debug uses).
    //Begin SpriteBatch
    spriteBatch.Begin(SpriteSortMode::Immediate, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);

    //Width + Height
    int width = 128;
    int height = 128;

    //Set up Drawing Rectangle
    Rectangle rect = Rectangle(0, 0, width, height);

    //Draw GBuffer 0
    spriteBatch.Draw(*static_cast<Texture2D*>(GBufferTargets[0].RenderTarget), rect, Color::White);

    //Draw GBuffer 1
    rect.X += width;
    spriteBatch.Draw(*static_cast<Texture2D*>(GBufferTargets[1].RenderTarget), rect, Color::White);

    //Draw GBuffer 2
    rect.X += width;
    spriteBatch.Draw(*static_cast<Texture2D*>(GBufferTargets[2].RenderTarget), rect, Color::White);

    //End SpriteBatch
    spriteBatch.End();
}

}  // namespace TheCansinDeferredRenderer
