// CubeGame: see cube_game.h.
#include "cube_game.h"

namespace example {

// Inside the game's namespace, as docs/API.md ("Names") advises: the game's own names win over XNA's.
using namespace fxport;

CubeGame::CubeGame(int width, int height, const std::string& contentRoot) {
    graphics.PreferredBackBufferWidth = width;  // headless (OSMesa) unless FXPORT_PLATFORM says egl or glfw
    graphics.PreferredBackBufferHeight = height;
    Content.RootDirectory = contentRoot;
}

void CubeGame::LoadContent() {
    fxport::GraphicsDevice& device = *GraphicsDevice;
    // PostProcess.fxeffect and Scanlines.fxeffect, compiled at build time by fxport_add_effects
    // (Effect::FromCompiledFile underneath: no HLSL compiler runs here).
    postProcess_ = Content.Load<Effect>("PostProcess");
    scanlines_ = Content.Load<Effect>("Scanlines");
    cube_ = Content.Load<Model>("Cube");
    // One grey key light and grey ambient on the material's colour; no highlights.
    for (ModelMesh& mesh : cube_->Meshes)
        for (Effect* effect : mesh.Effects())
            if (auto* basic = dynamic_cast<BasicEffect*>(effect)) {
                basic->LightingEnabled = true;
                basic->AmbientLightColor = Vector3(SceneSettings::Ambient);
                basic->SpecularColor = Vector3::Zero;
                basic->DirectionalLight0.Enabled = true;
                basic->DirectionalLight0.Direction = SceneSettings::LightDirection();
                basic->DirectionalLight0.DiffuseColor = Vector3(SceneSettings::LightDiffuse);
                basic->DirectionalLight1.Enabled = false;
                basic->DirectionalLight2.Enabled = false;
            }

    const PresentationParameters& pp = device.PresentationParameters();
    sceneTarget_ = std::make_unique<RenderTarget2D>(device, pp.BackBufferWidth, pp.BackBufferHeight, false,
                                                    SurfaceFormat::Color, DepthFormat::Depth24);
    gradedTarget_ = std::make_unique<RenderTarget2D>(device, pp.BackBufferWidth, pp.BackBufferHeight, false,
                                                     SurfaceFormat::Color, DepthFormat::None);
    spriteBatch_ = std::make_unique<SpriteBatch>(device);
    scanlines_->Parameters["ScreenHeight"].SetValue(float(pp.BackBufferHeight));

    view_ = Matrix::CreateLookAt(Vector3(0, 0, SceneSettings::CameraDistance), Vector3::Zero, Vector3::Up);
    projection_ = Matrix::CreatePerspectiveFieldOfView(SceneSettings::FieldOfView,
                                                       float(pp.BackBufferWidth) / float(pp.BackBufferHeight),
                                                       SceneSettings::NearPlane, SceneSettings::FarPlane);
}

void CubeGame::Update(const GameTime& gameTime) {
    sceneSeconds_ = gameTime.TotalGameTime.TotalSeconds();
    world_ = Matrix::CreateRotationY(SceneSettings::AngleAt(sceneSeconds_)) * Matrix::CreateRotationX(SceneSettings::Tilt);
}

void CubeGame::Draw(const GameTime& gameTime) {
    (void)gameTime;
    fxport::GraphicsDevice& device = *GraphicsDevice;

    // 1. The model into the scene target, with its BasicEffects.
    device.SetRenderTarget(*sceneTarget_);
    device.Clear(Color::CornflowerBlue);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::Default;
    device.RasterizerState = RasterizerState::CullCounterClockwise;
    cube_->Draw(world_, view_, projection_);

    // 2. Colour grading into a second target: SpriteBatch with a custom pixel shader.
    device.SetRenderTarget(*gradedTarget_);
    spriteBatch_->Begin(SpriteSortMode::Immediate, BlendState::Opaque, SamplerState::PointClamp, DepthStencilState::None,
                        RasterizerState::CullNone, *postProcess_);
    spriteBatch_->Draw(*sceneTarget_, Vector2(0, 0), Color::White);
    spriteBatch_->End();

    // 3. Scan lines onto the back buffer.
    device.SetRenderTarget(nullptr);
    spriteBatch_->Begin(SpriteSortMode::Immediate, BlendState::Opaque, SamplerState::PointClamp, DepthStencilState::None,
                        RasterizerState::CullNone, *scanlines_);
    spriteBatch_->Draw(*gradedTarget_, Vector2(0, 0), Color::White);
    spriteBatch_->End();
}

}  // namespace example
