// CubeGame: see cube_game.h.
#include "cube_game.h"

using namespace fxport;

namespace example {

CubeGame::CubeGame(int width, int height, const std::string& contentRoot) {
    graphics.PreferredBackBufferWidth = width;  // headless (OSMesa) unless FXPORT_PLATFORM says egl or glfw
    graphics.PreferredBackBufferHeight = height;
    Content.RootDirectory = contentRoot;
}

void CubeGame::LoadContent() {
    fxport::GraphicsDevice& device = *GraphicsDevice;
    // Scene.fxeffect and PostProcess.fxeffect, compiled at build time by fxport_add_effects
    // (Effect::FromCompiledFile underneath: no HLSL compiler runs here).
    sceneEffect_ = Content.Load<Effect>("Scene");
    postProcess_ = Content.Load<Effect>("PostProcess");
    cube_ = Content.Load<Model>("Cube");
    const PresentationParameters& pp = device.PresentationParameters();
    sceneTarget_ = std::make_unique<RenderTarget2D>(device, pp.BackBufferWidth, pp.BackBufferHeight, false,
                                                    SurfaceFormat::Color, DepthFormat::Depth24);
    spriteBatch_ = std::make_unique<SpriteBatch>(device);

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

    // 1. The model into the scene target.
    device.SetRenderTarget(*sceneTarget_);
    device.Clear(Color::CornflowerBlue);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::Default;
    device.RasterizerState = RasterizerState::CullCounterClockwise;
    std::vector<Matrix> transforms(std::size_t(cube_->Bones.Count()));
    cube_->CopyAbsoluteBoneTransformsTo(transforms);
    sceneEffect_->Parameters["View"].SetValue(view_);
    sceneEffect_->Parameters["Projection"].SetValue(projection_);
    for (ModelMesh& mesh : cube_->Meshes) {
        sceneEffect_->Parameters["World"].SetValue(transforms[std::size_t(mesh.ParentBone->Index)] * world_);
        for (ModelMeshPart& part : mesh.MeshParts) {
            device.SetVertexBuffer(part.VertexBuffer, part.VertexOffset);
            device.Indices = part.IndexBuffer;
            sceneEffect_->CurrentTechnique->Passes[0].Apply();
            device.DrawIndexedPrimitives(PrimitiveType::TriangleList, 0, 0, part.NumVertices, part.StartIndex,
                                         part.PrimitiveCount);
        }
    }

    // 2. Post-process onto the back buffer: SpriteBatch with a custom pixel shader.
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    device.Clear(Color::Black);
    spriteBatch_->Begin(SpriteSortMode::Immediate, BlendState::Opaque, SamplerState::PointClamp, DepthStencilState::None,
                        RasterizerState::CullNone, *postProcess_);
    spriteBatch_->Draw(*sceneTarget_, Vector2(0, 0), Color::White);
    spriteBatch_->End();
}

}  // namespace example
