// ShadowMapKey's casters: the same walk as LightManager::DrawModels, recording what each draw uses.
#include "deferred/Lights/shadow_map_key.h"

namespace TheCansinDeferredRenderer::Lights {

void ShadowMapKey::addCasters(const std::vector<Model*>& models) {
    add(models.size());
    for (const Model* model : models) {
        add(model);
        std::vector<Matrix> transforms(std::size_t(model->Bones.Count()));
        model->CopyAbsoluteBoneTransformsTo(transforms);
        for (const Matrix& m : transforms) add(m);
        for (const ModelMesh& mesh : model->Meshes) {
            add(mesh.ParentBone->Index);
            for (const ModelMeshPart& part : mesh.MeshParts) {
                add(part.VertexBuffer);
                add(part.IndexBuffer);
                add(part.VertexOffset);
                add(part.NumVertices);
                add(part.StartIndex);
                add(part.PrimitiveCount);
            }
        }
    }
}

}  // namespace TheCansinDeferredRenderer::Lights
