// CrateGame: the third example game. A crate modelled as DirectX .x files are (Content/Crate.x, its
// texture the DXT1-compressed Content/Crate.dds) comes through Content.Load<Model>, as an XNA game
// loads the models and textures it ships; its part's BasicEffect is set up from the .x material
// (texture on, lighting off) and drawn with the device's point sampler.
#pragma once

#include "fxport/framework.h"

namespace example {

// The scene's fixed values, shared with the CPU check (crate_check.cpp).
struct CrateScene {
    static constexpr float CameraDistance = 2.6f;  // on +Z, looking at the origin, +Y up
    static constexpr float FieldOfView = 0.78539816339744830962f;  // MathHelper.PiOver4
    static constexpr float NearPlane = 0.1f;
    static constexpr float FarPlane = 10.0f;
    static constexpr float Turn = 0.6f;  // rotation about Y, radians
    static constexpr float Tilt = 0.4f;  // then about X
};

class CrateGame : public fxport::Game {
public:
    CrateGame(int width, int height, const std::string& contentRoot);

protected:
    void LoadContent() override;
    void Draw(const fxport::GameTime& gameTime) override;

private:
    fxport::Model* crate_ = nullptr;
};

}  // namespace example
