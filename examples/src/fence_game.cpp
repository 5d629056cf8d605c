// FenceGame: see fence_game.h. The methods follow XNA's Game1 template, in XNA's order.
#include "fence_game.h"

namespace example {

// Inside the game's namespace, as docs/API.md ("Names") advises: the game's own names win over XNA's.
using namespace fxport;

FenceGame::FenceGame(int width, int height, const std::string& contentRoot) {
    graphics.PreferredBackBufferWidth = width;  // headless (OSMesa) unless FXPORT_PLATFORM says egl or glfw
    graphics.PreferredBackBufferHeight = height;
    Content.RootDirectory = contentRoot;
}

void FenceGame::Initialize() {
    Window.Title = "Fence Game";
    IsFixedTimeStep = true;  // XNA's default: Update every 1/60 s of game time
    // The fence, in world space: two triangles as a strip, texture (0, 0) at the top left.
    fenceVertices[0] = VertexPositionTexture(Vector3(FenceScene::FenceLeft, FenceScene::FenceTop, FenceScene::FenceZ), Vector2(0, 0));
    fenceVertices[1] = VertexPositionTexture(Vector3(FenceScene::FenceRight, FenceScene::FenceTop, FenceScene::FenceZ), Vector2(1, 0));
    fenceVertices[2] = VertexPositionTexture(Vector3(FenceScene::FenceLeft, FenceScene::FenceBottom, FenceScene::FenceZ), Vector2(0, 1));
    fenceVertices[3] = VertexPositionTexture(Vector3(FenceScene::FenceRight, FenceScene::FenceBottom, FenceScene::FenceZ), Vector2(1, 1));
    gateVertices[0] = VertexPositionTexture(Vector3(FenceScene::GateLeft, FenceScene::GateTop, FenceScene::FenceZ), Vector2(0, 0));
    gateVertices[1] = VertexPositionTexture(Vector3(FenceScene::GateRight, FenceScene::GateTop, FenceScene::FenceZ), Vector2(1, 0));
    gateVertices[2] = VertexPositionTexture(Vector3(FenceScene::GateLeft, FenceScene::GateBottom, FenceScene::FenceZ), Vector2(0, 1));
    gateVertices[3] = VertexPositionTexture(Vector3(FenceScene::GateRight, FenceScene::GateBottom, FenceScene::FenceZ), Vector2(1, 1));
    Game::Initialize();  // calls LoadContent, as XNA's base.Initialize() does
}

void FenceGame::LoadContent() {
    spriteBatch = std::make_unique<SpriteBatch>(*GraphicsDevice);

    crate = Content.Load<Model>("Cube");
    fenceEffect = Content.Load<Effect>("Fence");  // Fence.fxeffect, built from effects/Fence.fx
    // Premultiplied by alpha at load, as XNA's content pipeline did (ContentManager::textureProcessor).
    // The fence is drawn without blending, so only the alpha test reads the alpha.
    fenceTexture = Content.Load<Texture2D>("Fence");
    hudFont = Content.Load<SpriteFont>("Hud");

    // The model's parts carry BasicEffects made from the glTF material (its base colour is the
    // DiffuseColor); light them with XNA's three-light rig, per pixel.
    for (ModelMesh& mesh : crate->Meshes)
        for (Effect* effect : mesh.Effects())
            if (auto* basicEffect = dynamic_cast<BasicEffect*>(effect)) {
                basicEffect->EnableDefaultLighting();
                basicEffect->PreferPerPixelLighting = true;
            }

    fenceEffect->Parameters["FenceTexture"].SetValue(fenceTexture);
    fenceEffect->Parameters["Tint"].SetValue(FenceScene::FenceTint());

    // The gate: XNA's stock AlphaTestEffect, keeping texels whose alpha is above 128 as Fence.fx does.
    gateEffect = std::make_unique<AlphaTestEffect>(*GraphicsDevice);
    gateEffect->Texture = fenceTexture;
    gateEffect->AlphaFunction = CompareFunction::Greater;
    gateEffect->ReferenceAlpha = 128;

    const Viewport& viewport = GraphicsDevice->Viewport;
    view = Matrix::CreateLookAt(Vector3(0, 0, FenceScene::CameraDistance), Vector3::Zero, Vector3::Up);
    projection = Matrix::CreatePerspectiveFieldOfView(FenceScene::FieldOfView, viewport.AspectRatio(),
                                                      FenceScene::NearPlane, FenceScene::FarPlane);
}

void FenceGame::Update(const GameTime& gameTime) {
    sceneSeconds_ = gameTime.TotalGameTime.TotalSeconds();
    world = Matrix::CreateRotationY(FenceScene::CrateAngleAt(sceneSeconds_)) * Matrix::CreateRotationX(FenceScene::CrateTilt);
    score += FenceScene::PointsPerUpdate;
    hudText_ = "Score: " + std::to_string(score);
}

void FenceGame::Draw(const GameTime& gameTime) {
    (void)gameTime;
    GraphicsDevice->Clear(Color::CornflowerBlue);

    // SpriteBatch changed these last frame; 3D drawing wants them back (XNA's usual reset).
    GraphicsDevice->BlendState = BlendState::Opaque;
    GraphicsDevice->DepthStencilState = DepthStencilState::Default;
    GraphicsDevice->RasterizerState = RasterizerState::CullCounterClockwise;

    // The crate: Model.Draw sets World/View/Projection on each part's effect and draws.
    crate->Draw(world, view, projection);

    // The fence in front of it: no blending, the pass's alpha test drops the holes' pixels (and
    // their depth), so the crate and the sky show through.
    fenceEffect->Parameters["World"].SetValue(Matrix::Identity);
    fenceEffect->Parameters["View"].SetValue(view);
    fenceEffect->Parameters["Projection"].SetValue(projection);
    for (EffectPass& pass : fenceEffect->CurrentTechnique->Passes) {
        pass.Apply();
        GraphicsDevice->DrawUserPrimitives(PrimitiveType::TriangleStrip, fenceVertices, 0, 2);
    }

    // The gate: AlphaTestEffect samples through register 0, filtered as SamplerStates[0] says.
    GraphicsDevice->SamplerStates[0] = SamplerState::PointClamp;
    gateEffect->World = Matrix::Identity;
    gateEffect->View = view;
    gateEffect->Projection = projection;
    for (EffectPass& pass : gateEffect->CurrentTechnique->Passes) {
        pass.Apply();
        GraphicsDevice->DrawUserPrimitives(PrimitiveType::TriangleStrip, gateVertices, 0, 2);
    }

    // The HUD on top.
    spriteBatch->Begin();
    spriteBatch->DrawString(*hudFont, hudText_, FenceScene::HudPosition(), Color::White);
    spriteBatch->End();
}

}  // namespace example
