#include "deferred/game1.h"

#include <algorithm>
#include <array>
#include <optional>
#include <string>

namespace TheCansinDeferredRenderer {

namespace {

// fxport: the DemoSettings knobs, checked before anything is created.
void checkRange(const char* setting, int value, int lo, int hi) {
    if (value < lo || value > hi)
        throw ArgumentError(std::string("Game1::DemoSettings::") + setting + " = " + std::to_string(value) +
                            " is outside " + std::to_string(lo) + ".." + std::to_string(hi));
}

std::array<SurfaceFormat, 3> gbufferFormatsOf(Game1::DemoSettings::GBufferFormats formats) {
    switch (formats) {
    case Game1::DemoSettings::GBufferFormats::Tutorial:
        return {SurfaceFormat::Rgba64, SurfaceFormat::Rgba64, SurfaceFormat::Vector2};
    case Game1::DemoSettings::GBufferFormats::Color8:
        return {SurfaceFormat::Color, SurfaceFormat::Color, SurfaceFormat::Single};
    case Game1::DemoSettings::GBufferFormats::Float32:
        return {SurfaceFormat::Vector4, SurfaceFormat::Vector4, SurfaceFormat::Vector4};
    }
    throw ArgumentError("Game1::DemoSettings::gbufferFormats = " + std::to_string(int(formats)) + " is not a GBufferFormats");
}

}  // namespace

SSAO& Game1::getSSAO() {
    if (!ssao) throw InvalidOperation("Game1::getSSAO: SSAO is off (DemoSettings::ssao = false)");
    return *ssao;
}

RenderTarget2D& Game1::getScene() {
    if (!Scene) throw InvalidOperation("Game1::getScene: no Scene target without SSAO (DemoSettings::ssao = false)");
    return *Scene;
}

Game1::Game1() {
    // graphics = new GraphicsDeviceManager(this): the Game base holds it.
    Content.RootDirectory = FXPORT_CONTENT_DIR;
    // fxport: the effects are compiled from their sources (hlsl/xna-deferred), not from a content project.
    Content.EffectDirectory = FXPORT_HLSL_DIR "/xna-deferred";
    graphics.PreferredBackBufferWidth = 800;
    graphics.PreferredBackBufferHeight = 600;
}

void Game1::Initialize() {
    //Initialize Camera
    Camera = std::make_unique<FreeCamera>(*this, demo.cameraPosition, demo.cameraTarget, Vector3::Up);
    Game::Initialize();
}

void Game1::LoadContent() {
    // Create a new SpriteBatch, which can be used to draw textures.
    spriteBatch = std::make_unique<SpriteBatch>(*GraphicsDevice);

    //Create spriteFont
    // fxport: the built-in debug font stands for the tutorial's DefaultFont.spritefont (not in the seed).
    debugFont = SpriteFont::createDebugFont(*GraphicsDevice);
    spriteFont = debugFont.get();

    // fxport: the knobs (DemoSettings) are checked before anything is made.
    checkRange("spotShadowMapSize", demo.spotShadowMapSize, 256, 4096);
    checkRange("pointShadowMapSize", demo.pointShadowMapSize, 64, 1024);

    //Create Deferred Renderer
    deferredRenderer = std::make_unique<DeferredRenderer>(*GraphicsDevice, Content, graphics.PreferredBackBufferWidth,
                                                          graphics.PreferredBackBufferHeight,
                                                          gbufferFormatsOf(demo.gbufferFormats));

    // fxport: SSAO and the Scene target it reads exist only with DemoSettings::ssao (the seed always
    // makes them); without, Draw renders the composition straight to the back buffer, as F1 does.
    if (demo.ssao) {
        //Create SSAO
        const int ssaoDivisor = demo.ssaoHalfResolution ? 2 : 1;
        ssao = std::make_unique<SSAO>(*GraphicsDevice, Content,
                                      std::max(1, graphics.PreferredBackBufferWidth / ssaoDivisor),
                                      std::max(1, graphics.PreferredBackBufferHeight / ssaoDivisor));

        //Create Scene Render Target
        Scene = std::make_unique<RenderTarget2D>(*GraphicsDevice, graphics.PreferredBackBufferWidth,
                                                 graphics.PreferredBackBufferHeight, false, SurfaceFormat::Color,
                                                 DepthFormat::Depth24Stencil8);
        Scene->Name = "Scene";
    }

    //Create Light Manager
    lightManager = std::make_unique<Lights::LightManager>(Content);
    lightManager->reuseShadowMaps = demo.reuseShadowMaps;

    //Load SpotLight Cookies
    Texture2D* spotCookie = Content.Load<Texture2D>("SpotCookie");
    Texture2D* squareCookie = Content.Load<Texture2D>("SquareCookie");
    (void)squareCookie;

    //Add a Directional Light
    lightManager->AddLight(std::make_unique<Lights::DirectionalLight>(Vector3::Down, Color::White, 0.05f));

    //Add a Spot Light
    lightManager->AddLight(std::make_unique<Lights::SpotLight>(*GraphicsDevice, Vector3(0, 15.0f, 0), Vector3(0, -1, 0),
                                                               Color::White.ToVector4(), 0.10f, true, demo.spotShadowMapSize,
                                                               spotCookie));

    //Add a Point Light
    lightManager->AddLight(std::make_unique<Lights::PointLight>(*GraphicsDevice, Vector3(0, 5.0f, 0), 20.0f,
                                                                Color::White.ToVector4(), 0.80f, true,
                                                                demo.pointShadowMapSize));

    //Initialize Model List
    models = std::vector<Model*>();

    //Load Models
    Model* scene = Content.Load<Model>("Scene");
    models.push_back(scene);

    // fxport: the demo's starting values (see DemoSettings).
    if (ssao) {
        ssao->setSampleRadius(demo.sampleRadius);
        ssao->setDistanceScale(demo.distanceScale);
    }
}

void Game1::UnloadContent() {}

void Game1::Update(const GameTime& gameTime) {
    //Input Housekeeping
    previousK = currentK;
    currentK = Keyboard::GetState();
    currentM = Mouse::GetState();
    // Mouse.SetPosition(GraphicsDevice.Viewport.Width / 2, GraphicsDevice.Viewport.Height / 2):
    // fxport's Mouse has no SetPosition; FreeCamera turns by the change since the last Update.

    //Exit check
    if (currentK.IsKeyUp(Keys::Escape) && previousK.IsKeyDown(Keys::Escape)) this->Exit();

    //Update Camera
    Camera->Update(*this, currentK, previousK, currentM);

    //Modify
    if (ssao) ssao->Modify(currentK);

    Game::Update(gameTime);
}

void Game1::Draw(const GameTime& gameTime) {
    //Clear
    GraphicsDevice->Clear(Color::CornflowerBlue);

    //Draw Shadow Maps
    // fxport: only lights with shadows that the camera sees get (and draw) a shadow map; without any
    // shadowed light there is no ShadowMaps pass (DrawShadowMaps still updates the spot lights).
    {
        std::optional<PassTimer> timed;
        if (lightManager->HasShadowedLights()) timed.emplace(demo.gpuTimer, "ShadowMaps");
        lightManager->DrawShadowMaps(
            *GraphicsDevice, models,
            [&](const Lights::SpotLight& light) { return deferredRenderer->IsVisible(light, *Camera); },
            [&](const Lights::PointLight& light) { return deferredRenderer->IsVisible(light, *Camera); });
    }

    //Draw with SSAO unless F1 is down
    if (currentK.IsKeyDown(Keys::F1) || !ssao) {
        //Draw using Deferred Renderer straight to BackBuffer
        deferredRenderer->Draw(*GraphicsDevice, models, *lightManager, *Camera, nullptr);
    } else {
        //Draw using Deferred Renderer
        deferredRenderer->Draw(*GraphicsDevice, models, *lightManager, *Camera, Scene.get());

        //Draw non blurred ssao
        ssao->Draw(*GraphicsDevice, deferredRenderer->getGBuffer(), Scene.get(), *Camera, nullptr);
    }

    if (demo.debugViews) {
        PassTimer timed(demo.gpuTimer, "Debug");

        //Debug Deferred Renderer
        deferredRenderer->Debug(*GraphicsDevice, *spriteBatch);

        //Debug SSAO
        if (ssao) ssao->Debug(*spriteBatch, *spriteFont);
    }

    //Base Drawing
    Game::Draw(gameTime);
}

}  // namespace TheCansinDeferredRenderer
