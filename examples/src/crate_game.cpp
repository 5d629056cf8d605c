// CrateGame: see crate_game.h.
#include "crate_game.h"

namespace example {

// Inside the game's namespace, as docs/API.md ("Names") advises: the game's own names win over XNA's.
using namespace fxport;

CrateGame::CrateGame(int width, int height, const std::string& contentRoot) {
    graphics.PreferredBackBufferWidth = width;  // headless (OSMesa) unless FXPORT_PLATFORM says egl or glfw
    graphics.PreferredBackBufferHeight = height;
    Content.RootDirectory = contentRoot;
}

void CrateGame::LoadContent() { crate_ = Content.Load<Model>("Crate"); }

void CrateGame::Draw(const GameTime&) {
    fxport::GraphicsDevice& device = *GraphicsDevice;
    device.Clear(Color::CornflowerBlue);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::Default;
    device.RasterizerState = RasterizerState::CullCounterClockwise;
    device.SamplerStates[0] = SamplerState::PointClamp;
    const PresentationParameters& pp = device.PresentationParameters();
    const Matrix world = Matrix::CreateRotationY(CrateScene::Turn) * Matrix::CreateRotationX(CrateScene::Tilt);
    const Matrix view = Matrix::CreateLookAt(Vector3(0, 0, CrateScene::CameraDistance), Vector3::Zero, Vector3::Up);
    const Matrix projection = Matrix::CreatePerspectiveFieldOfView(
        CrateScene::FieldOfView, float(pp.BackBufferWidth) / float(pp.BackBufferHeight), CrateScene::NearPlane, CrateScene::FarPlane);
    crate_->Draw(world, view, projection);
}

}  // namespace example
