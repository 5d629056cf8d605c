// CubeGame: the example game, written as an XNA 4 Game1 is: LoadContent loads a model and two
// effects compiled at build time (fxport_add_effects; Content.Load<Effect> finds Name.fxeffect),
// Update turns the model, Draw renders it into a render target and post-processes that onto the
// back buffer through SpriteBatch with a custom effect.
#pragma once

#include <memory>
#include <string>

#include "fxport/framework.h"
#include "fxport/graphics.h"

namespace example {

// The scene's fixed values, shared with the CPU check (frame_check.cpp).
struct SceneSettings {
    static constexpr float CameraDistance = 2.6f;
    static constexpr float FieldOfView = 0.78539816339744830962f;  // MathHelper.PiOver4
    static constexpr float NearPlane = 0.1f;
    static constexpr float FarPlane = 10.0f;
    static constexpr float Tilt = 0.45f;            // rotation about X, radians
    static constexpr float StartAngle = 0.6f;       // rotation about Y at time 0
    static constexpr float RadiansPerSecond = 0.8f;  // rotation about Y
    static float AngleAt(double totalSeconds) { return StartAngle + RadiansPerSecond * float(totalSeconds); }
};

class CubeGame : public fxport::Game {
public:
    // `contentRoot`: the folder with the compiled effects and the model (XNA's Content.RootDirectory).
    CubeGame(int width, int height, const std::string& contentRoot);

    // The game time the last Update placed the cube at (for the CPU check).
    double SceneSeconds() const { return sceneSeconds_; }

protected:
    void LoadContent() override;
    void Update(const fxport::GameTime& gameTime) override;
    void Draw(const fxport::GameTime& gameTime) override;

private:
    fxport::Model* cube_ = nullptr;
    fxport::Effect* sceneEffect_ = nullptr;
    fxport::Effect* postProcess_ = nullptr;
    std::unique_ptr<fxport::RenderTarget2D> sceneTarget_;
    std::unique_ptr<fxport::SpriteBatch> spriteBatch_;
    fxport::Matrix world_ = fxport::Matrix::Identity;
    fxport::Matrix view_ = fxport::Matrix::Identity;
    fxport::Matrix projection_ = fxport::Matrix::Identity;
    double sceneSeconds_ = 0;
};

}  // namespace example
