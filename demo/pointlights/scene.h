// Scene (the series' scene class, chapter 2; not in seed 001, reconstructed): loads the models and
// draws them into the G-buffer with RenderGBuffer.fx. The series draws its ship model; fxport draws
// the deferred demo's generated Scene.gltf (the courtyard of content/README.md).
#pragma once

#include <vector>

#include "pointlights/camera.h"
#include "pointlights/xna.h"

namespace DeferredLighting {

class Scene {
    Effect* renderGBufferEffect = nullptr;
    std::vector<Model*> models;

public:
    void InitializeScene(ContentManager& Content);
    void DrawScene(GraphicsDevice& GraphicsDevice, Camera& camera, const GameTime& gameTime);
};

}  // namespace DeferredLighting
