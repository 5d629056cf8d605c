// Game1 (seed 001's series, Catalin Zima): the game holds the camera, the scene, the quad renderer
// and the DeferredRenderer; the chapter's one directional light and 22 animated point lights are
// drawn by DeferredRenderer::DrawLights from the game time.
#pragma once

#include <memory>
#include <optional>

#include "pointlights/camera.h"
#include "pointlights/deferred_renderer.h"
#include "pointlights/quad_renderer.h"
#include "pointlights/scene.h"
#include "pointlights/xna.h"

namespace DeferredLighting {

class Game1 : public Game {
    std::unique_ptr<Camera> camera;
    std::unique_ptr<QuadRenderer> quadRenderer;
    std::unique_ptr<Scene> scene;
    std::unique_ptr<DeferredRenderer> renderer;
    KeyboardState currentK;
    KeyboardState previousK;

public:
    Game1();

    // fxport additions, for fxdemo: chosen before Start(), read after the frames.
    struct DemoSettings {
        // --time T: every frame is drawn at game time T (a reproducible frame); unset: the game's
        // own clock (1/60 s per frame).
        std::optional<double> time;
        // Orbit camera start (degrees, degrees, units) and target.
        float cameraArc = -25.0f;
        float cameraRotation = 0.0f;
        float cameraDistance = 20.0f;
        // fxport (fxdemo report): G-buffer formats, light count, light-sphere tessellation.
        DeferredRenderer::Quality quality;
    };
    DemoSettings demo;
    DeferredRenderer& getRenderer() { return *renderer; }
    Camera& getCamera() { return *camera; }

protected:
    void Initialize() override;
    void LoadContent() override;
    void Update(const GameTime& gameTime) override;
    void Draw(const GameTime& gameTime) override;
};

}  // namespace DeferredLighting
