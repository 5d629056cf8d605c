// FenceGame: the second example game, a port of a small XNA 4 Game1. A crate (Content/Cube.gltf: its
// part gets a BasicEffect from the glTF material, lit here with EnableDefaultLighting, per pixel)
// turns in a yard behind a wooden lattice fence, drawn with the game's own effect Fence.fx, whose
// pass cuts the holes with the D3D9 alpha test (AlphaTestEnable / AlphaFunc / AlphaRef) on the
// texture Fence.png; beside it a gate of the same lattice is drawn with XNA's stock AlphaTestEffect;
// a HUD line shows the score in a SpriteFont (Hud.spritefont: DejaVu Sans, 14 pt).
// Everything comes through the ContentManager: Load<Model>, Load<Effect> (Fence.fxeffect, compiled
// while the game builds by fxport_add_effects), Load<Texture2D>, Load<SpriteFont>.
#pragma once

#include <memory>
#include <string>

#include "fxport/framework.h"

namespace example {

// The yard's fixed values, shared with the CPU check (fence_check.cpp).
struct FenceScene {
    static constexpr float CameraDistance = 3.0f;  // on +Z, looking at the origin, +Y up
    static constexpr float FieldOfView = 0.78539816339744830962f;  // MathHelper.PiOver4
    static constexpr float NearPlane = 0.1f;
    static constexpr float FarPlane = 10.0f;
    static constexpr float CrateTilt = 0.5f;              // rotation about X, radians
    static constexpr float CrateStartAngle = 0.7f;        // rotation about Y at time 0
    static constexpr float CrateRadiansPerSecond = 0.6f;  // rotation about Y
    // The fence: a quad facing the camera at z = FenceZ (between the camera and the crate).
    static constexpr float FenceZ = 1.2f;
    static constexpr float FenceLeft = -0.15f, FenceRight = 0.75f, FenceBottom = -0.7f, FenceTop = 0.2f;
    static fxport::Vector3 FenceTint() { return fxport::Vector3(1.0f, 0.92f, 0.85f); }  // weathered wood
    // The gate: the same texture, at the same depth, left of the fence (AlphaTestEffect, untinted).
    static constexpr float GateLeft = -0.95f, GateRight = -0.35f, GateBottom = -0.6f, GateTop = 0.0f;
    static constexpr int PointsPerUpdate = 10;
    static fxport::Vector2 HudPosition() { return fxport::Vector2(10, 8); }
    static float CrateAngleAt(double totalSeconds) { return CrateStartAngle + CrateRadiansPerSecond * float(totalSeconds); }
};

class FenceGame : public fxport::Game {
public:
    // `contentRoot`: the folder with the compiled effect, the model, the texture and the font.
    FenceGame(int width, int height, const std::string& contentRoot);

    // What the last frame showed, for the CPU check.
    double SceneSeconds() const { return sceneSeconds_; }
    const std::string& HudText() const { return hudText_; }
    const fxport::SpriteFont& HudFont() const { return *hudFont; }

protected:
    void Initialize() override;
    void LoadContent() override;
    void Update(const fxport::GameTime& gameTime) override;
    void Draw(const fxport::GameTime& gameTime) override;

private:
    // Named as the fields of an XNA Game1.
    std::unique_ptr<fxport::SpriteBatch> spriteBatch;
    fxport::Model* crate = nullptr;
    fxport::Effect* fenceEffect = nullptr;
    fxport::Texture2D* fenceTexture = nullptr;
    fxport::SpriteFont* hudFont = nullptr;
    std::unique_ptr<fxport::AlphaTestEffect> gateEffect;
    fxport::VertexPositionTexture fenceVertices[4];
    fxport::VertexPositionTexture gateVertices[4];
    fxport::Matrix world = fxport::Matrix::Identity;
    fxport::Matrix view = fxport::Matrix::Identity;
    fxport::Matrix projection = fxport::Matrix::Identity;
    int score = 0;
    std::string hudText_;
    double sceneSeconds_ = 0;
};

}  // namespace example
