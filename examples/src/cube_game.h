// CubeGame: the example game, written as an XNA 4 Game1 is. LoadContent loads a glTF model (its
// parts get BasicEffects from the material) and two post effects compiled at build time
// (fxport_add_effects; Content.Load<Effect> finds Name.fxeffect) and lights the model; Update turns
// it; Draw renders it with Model.Draw into a render target, grades that into a second target
// through SpriteBatch with PostProcess.fx, and draws the result onto the back buffer with
// Scanlines.fx.
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
    static constexpr float Ambient = 0.25f;         // BasicEffect.AmbientLightColor (grey)
    static constexpr float LightDiffuse = 0.75f;    // DirectionalLight0.DiffuseColor (grey)
    static fxport::Vector3 LightDirection() { return fxport::Vector3::Normalize(fxport::Vector3(-0.5f, -0.7f, -0.5f)); }
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
    fxport::Effect* postProcess_ = nullptr;
    fxport::Effect* scanlines_ = nullptr;
    std::unique_ptr<fxport::RenderTarget2D> sceneTarget_;
    std::unique_ptr<fxport::RenderTarget2D> gradedTarget_;
    std::unique_ptr<fxport::SpriteBatch> spriteBatch_;
    fxport::Matrix world_ = fxport::Matrix::Identity;
    fxport::Matrix view_ = fxport::Matrix::Identity;
    fxport::Matrix projection_ = fxport::Matrix::Identity;
    double sceneSeconds_ = 0;
};

}  // namespace example
