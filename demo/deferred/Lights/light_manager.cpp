#include "deferred/Lights/light_manager.h"

#include <algorithm>

namespace TheCansinDeferredRenderer::Lights {

namespace {

// C#'s List<T>.Remove(item) for a list of owning pointers.
template <class T>
void removeFrom(std::vector<std::unique_ptr<T>>& list, T* item) {
    auto it = std::find_if(list.begin(), list.end(), [&](const std::unique_ptr<T>& p) { return p.get() == item; });
    if (it != list.end()) list.erase(it);
}

}  // namespace

//Constructor
LightManager::LightManager(ContentManager& Content) : content(Content) {
    //Initialize Directional Lights
    directionalLights.clear();
    //Initialize Spot Lights
    spotLights.clear();
    //Initialize Point Lights
    pointLights.clear();
    //Load the Depth Writing Shader
    // fxport: in DrawShadowMaps, when the first shadow map is drawn.
}

bool LightManager::HasShadowedLights() const {
    for (auto& Light : spotLights)
        if (Light->getIsWithShadows()) return true;
    for (auto& Light : pointLights)
        if (Light->getIsWithShadows()) return true;
    return false;
}

//Add a Directional Light
void LightManager::AddLight(std::unique_ptr<DirectionalLight> Light) { directionalLights.push_back(std::move(Light)); }

//Add a Spot Light
void LightManager::AddLight(std::unique_ptr<SpotLight> Light) { spotLights.push_back(std::move(Light)); }

//Add a Point Light
void LightManager::AddLight(std::unique_ptr<PointLight> Light) { pointLights.push_back(std::move(Light)); }

//Remove a Directional Light
void LightManager::RemoveLight(DirectionalLight* Light) { removeFrom(directionalLights, Light); }

//Remove a Spot Light
void LightManager::RemoveLight(SpotLight* Light) {
    shadowMapKeys.erase(Light);  // fxport: a later light at the same address starts without a map
    removeFrom(spotLights, Light);
}

//Remove a Point Light
void LightManager::RemoveLight(PointLight* Light) {
    shadowMapKeys.erase(Light);
    removeFrom(pointLights, Light);
}

bool LightManager::ShadowMapOutdated(const void* Light, const ShadowMapKey& key) {
    auto found = shadowMapKeys.find(Light);
    if (reuseShadowMaps && found != shadowMapKeys.end() && found->second == key) {
        ++shadowMapsReused;
        return false;
    }
    shadowMapKeys[Light] = key;
    ++shadowMapsDrawn;
    return true;
}

//Draw Shadow Maps
void LightManager::DrawShadowMaps(GraphicsDevice& GraphicsDevice, const std::vector<Model*>& Models,
                                  const std::function<bool(const SpotLight&)>& spotVisible,
                                  const std::function<bool(const PointLight&)>& pointVisible) {
    // fxport: the depth writer is compiled the first time a shadow map is drawn.
    auto needDepthWriter = [&] {
        if (depthWriter) return;
        //Load the Depth Writing Shader
        depthWriter = content.Load<Effect>("Effects/DepthWriter");
        depthWriter->CurrentTechnique = depthWriter->Techniques[0];
    };

    //Set States
    GraphicsDevice.BlendState = BlendState::Opaque;
    GraphicsDevice.DepthStencilState = DepthStencilState::Default;
    GraphicsDevice.RasterizerState = RasterizerState::CullCounterClockwise;

    //Foreach SpotLight with Shadows
    for (auto& Light : spotLights) {
        //Update it
        Light->Update();

        //Draw it's Shadow Map
        if (Light->getIsWithShadows() && (!spotVisible || spotVisible(*Light))) {
            needDepthWriter();
            // fxport (issue 16): what DrawShadowMap(SpotLight) draws from.
            ShadowMapKey key;
            key.add(&Light->MakeShadowMap());
            key.add(Light->getShadowMapResoloution());
            key.add(depthWriter);
            key.add(Light->getView());
            key.add(Light->getProjection());
            key.add(Light->getPosition());
            key.add(Light->getFarPlane());
            key.addCasters(Models);
            if (ShadowMapOutdated(Light.get(), key)) DrawShadowMap(GraphicsDevice, *Light, Models);
        }
    }

    //Foreach PointLight with Shadows
    for (auto& Light : pointLights) {
        //Draw it's Shadow Map
        if (Light->getIsWithShadows() && (!pointVisible || pointVisible(*Light))) {
            needDepthWriter();
            // fxport (issue 16): what DrawShadowMap(PointLight) draws from (its views and
            // projection follow from the position and radius).
            ShadowMapKey key;
            key.add(&Light->MakeShadowMap());
            key.add(Light->getShadowMapResoloution());
            key.add(depthWriter);
            key.add(Light->getPosition());
            key.add(Light->getRadius());
            key.addCasters(Models);
            if (ShadowMapOutdated(Light.get(), key)) DrawShadowMap(GraphicsDevice, *Light, Models);
        }
    }
}

//Draw a Shadow Map for a Spot Light
void LightManager::DrawShadowMap(GraphicsDevice& GraphicsDevice, SpotLight& Light, const std::vector<Model*>& Models) {
    //Set Light's Target onto the Graphics Device
    GraphicsDevice.SetRenderTarget(&Light.MakeShadowMap());

    //Clear Target
    GraphicsDevice.Clear(Color::Transparent);

    //Set global Effect parameters
    depthWriter->Parameters["View"].SetValue(Light.getView());
    depthWriter->Parameters["Projection"].SetValue(Light.getProjection());
    depthWriter->Parameters["LightPosition"].SetValue(Light.getPosition());
    depthWriter->Parameters["DepthPrecision"].SetValue(Light.getFarPlane());

    //Draw Models
    DrawModels(GraphicsDevice, Models);
}

//Draw a Shadow Map for a Point Light
void LightManager::DrawShadowMap(GraphicsDevice& GraphicsDevice, PointLight& Light, const std::vector<Model*>& Models) {
    //Initialize View Matrices Array
    Matrix views[6];
    //Create View Matrices
    views[0] = Matrix::CreateLookAt(Light.getPosition(), Light.getPosition() + Vector3::Forward, Vector3::Up);
    views[1] = Matrix::CreateLookAt(Light.getPosition(), Light.getPosition() + Vector3::Backward, Vector3::Up);
    views[2] = Matrix::CreateLookAt(Light.getPosition(), Light.getPosition() + Vector3::Left, Vector3::Up);
    views[3] = Matrix::CreateLookAt(Light.getPosition(), Light.getPosition() + Vector3::Right, Vector3::Up);
    views[4] = Matrix::CreateLookAt(Light.getPosition(), Light.getPosition() + Vector3::Down, Vector3::Forward);
    views[5] = Matrix::CreateLookAt(Light.getPosition(), Light.getPosition() + Vector3::Up, Vector3::Backward);

    //Create Projection Matrix
    Matrix projection = Matrix::CreatePerspectiveFieldOfView(MathHelper::ToRadians(90.0f), 1.0f, 1.0f, Light.getRadius());

    //Set Global Effect Values
    depthWriter->Parameters["Projection"].SetValue(projection);
    depthWriter->Parameters["LightPosition"].SetValue(Light.getPosition());
    depthWriter->Parameters["DepthPrecision"].SetValue(Light.getRadius());

    // #region Forward
    GraphicsDevice.SetRenderTarget(&Light.MakeShadowMap(), CubeMapFace::PositiveZ);
    //Clear Target
    GraphicsDevice.Clear(Color::Transparent);
    //Set global Effect parameters
    depthWriter->Parameters["View"].SetValue(views[0]);
    //Draw Models
    DrawModels(GraphicsDevice, Models);
    // #endregion

    // #region Backward
    GraphicsDevice.SetRenderTarget(&Light.MakeShadowMap(), CubeMapFace::NegativeZ);
    //Clear Target
    GraphicsDevice.Clear(Color::Transparent);
    //Set global Effect parameters
    depthWriter->Parameters["View"].SetValue(views[1]);
    //Draw Models
    DrawModels(GraphicsDevice, Models);
    // #endregion

    // #region Left
    GraphicsDevice.SetRenderTarget(&Light.MakeShadowMap(), CubeMapFace::NegativeX);
    //Clear Target
    GraphicsDevice.Clear(Color::Transparent);
    //Set global Effect parameters
    depthWriter->Parameters["View"].SetValue(views[2]);
    //Draw Models
    DrawModels(GraphicsDevice, Models);
    // #endregion

    // #region Right
    GraphicsDevice.SetRenderTarget(&Light.MakeShadowMap(), CubeMapFace::PositiveX);
    //Clear Target
    GraphicsDevice.Clear(Color::Transparent);
    //Set global Effect parameters
    depthWriter->Parameters["View"].SetValue(views[3]);
    //Draw Models
    DrawModels(GraphicsDevice, Models);
    // #endregion

    // #region Down
    GraphicsDevice.SetRenderTarget(&Light.MakeShadowMap(), CubeMapFace::NegativeY);
    //Clear Target
    GraphicsDevice.Clear(Color::Transparent);
    //Set global Effect parameters
    depthWriter->Parameters["View"].SetValue(views[4]);
    //Draw Models
    DrawModels(GraphicsDevice, Models);
    // #endregion

    // #region Up
    GraphicsDevice.SetRenderTarget(&Light.MakeShadowMap(), CubeMapFace::PositiveY);
    //Clear Target
    GraphicsDevice.Clear(Color::Transparent);
    //Set global Effect parameters
    depthWriter->Parameters["View"].SetValue(views[5]);
    //Draw Models
    DrawModels(GraphicsDevice, Models);
    // #endregion
}

//Draw Models
void LightManager::DrawModels(GraphicsDevice& GraphicsDevice, const std::vector<Model*>& Models) {
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
                depthWriter->Parameters["World"].SetValue(transforms[std::size_t(mesh.ParentBone->Index)]);
                //Apply Effect
                depthWriter->CurrentTechnique->Passes[0].Apply();
                // Reconstructed: seed 000 is cut here (the listing stops after Apply(); the draw is the
                // one of the light volumes in MakeLightMap, with the part's counts).
                //Draw
                GraphicsDevice.DrawIndexedPrimitives(PrimitiveType::TriangleList, 0, 0, part.NumVertices,
                                                     part.StartIndex, part.PrimitiveCount);
            }
        }
    }
}

}  // namespace TheCansinDeferredRenderer::Lights
