// CubeGame: see cube_game.h.
#include "cube_game.h"

using namespace fxport;

namespace example {

CubeGame::CubeGame(int width, int height, std::string contentRoot) : contentRoot_(std::move(contentRoot)) {
    PresentationParameters parameters;
    parameters.BackBufferWidth = width;
    parameters.BackBufferHeight = height;
    device_ = std::make_unique<fxport::GraphicsDevice>(parameters);  // OSMesa unless FXPORT_PLATFORM says otherwise
}

void CubeGame::LoadContent() {
    fxport::GraphicsDevice& device = *device_;
    // Compiled at build time by fxport_add_effects: loading them runs no HLSL compiler.
    sceneEffect_ = Effect::FromCompiledFile(device, contentRoot_ + "/Scene.fxeffect");
    postProcess_ = Effect::FromCompiledFile(device, contentRoot_ + "/PostProcess.fxeffect");
    cube_ = Model::Load(device, contentRoot_ + "/Cube.gltf");
    const PresentationParameters& pp = device.PresentationParameters();
    sceneTarget_ = std::make_unique<RenderTarget2D>(device, pp.BackBufferWidth, pp.BackBufferHeight, false,
                                                    SurfaceFormat::Color, DepthFormat::Depth24);
    spriteBatch_ = std::make_unique<SpriteBatch>(device);

    view_ = Matrix::CreateLookAt(Vector3(0, 0, SceneSettings::CameraDistance), Vector3::Zero, Vector3::Up);
    projection_ = Matrix::CreatePerspectiveFieldOfView(SceneSettings::FieldOfView,
                                                       float(pp.BackBufferWidth) / float(pp.BackBufferHeight),
                                                       SceneSettings::NearPlane, SceneSettings::FarPlane);
}

void CubeGame::Update(double totalSeconds) {
    world_ = Matrix::CreateRotationY(SceneSettings::AngleAt(totalSeconds)) * Matrix::CreateRotationX(SceneSettings::Tilt);
}

void CubeGame::Draw() {
    fxport::GraphicsDevice& device = *device_;

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
