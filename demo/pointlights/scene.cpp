#include "pointlights/scene.h"

namespace DeferredLighting {

void Scene::InitializeScene(ContentManager& Content) {
    renderGBufferEffect = Content.Load<Effect>("RenderGBuffer");
    models.push_back(Content.Load<Model>("Scene"));
}

void Scene::DrawScene(GraphicsDevice& GraphicsDevice, Camera& camera, const GameTime& gameTime) {
    (void)gameTime;
    GraphicsDevice.DepthStencilState = DepthStencilState::Default;
    GraphicsDevice.RasterizerState = RasterizerState::CullCounterClockwise;
    GraphicsDevice.BlendState = BlendState::Opaque;
    for (Model* model : models) {
        std::vector<Matrix> transforms(std::size_t(model->Bones.Count()));
        model->CopyAbsoluteBoneTransformsTo(transforms);
        for (ModelMesh& mesh : model->Meshes) {
            for (ModelMeshPart& part : mesh.MeshParts) {
                renderGBufferEffect->Parameters["World"].SetValue(transforms[std::size_t(mesh.ParentBone->Index)]);
                renderGBufferEffect->Parameters["View"].SetValue(camera.View);
                renderGBufferEffect->Parameters["Projection"].SetValue(camera.Projection);
                renderGBufferEffect->Parameters["Texture"].SetValue(
                    part.Effect->Parameters["Texture"].GetValueTexture2D());
                renderGBufferEffect->Techniques[0]->Passes[0].Apply();
                GraphicsDevice.SetVertexBuffer(part.VertexBuffer, part.VertexOffset);
                GraphicsDevice.Indices = part.IndexBuffer;
                GraphicsDevice.DrawIndexedPrimitives(PrimitiveType::TriangleList, 0, 0, part.NumVertices,
                                                     part.StartIndex, part.PrimitiveCount);
            }
        }
    }
}

}  // namespace DeferredLighting
