#include "deferred/game1.h"

namespace TheCansinDeferredRenderer {

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
    spriteFont = Content.Load<SpriteFont>("DefaultFont");

    //Create Deferred Renderer
    deferredRenderer = std::make_unique<DeferredRenderer>(*GraphicsDevice, Content, graphics.PreferredBackBufferWidth,
                                                          graphics.PreferredBackBufferHeight);

    //Create SSAO
    ssao = std::make_unique<SSAO>(*GraphicsDevice, Content, graphics.PreferredBackBufferWidth,
                                  graphics.PreferredBackBufferHeight);

    //Create Scene Render Target
    Scene = std::make_unique<RenderTarget2D>(*GraphicsDevice, graphics.PreferredBackBufferWidth,
                                             graphics.PreferredBackBufferHeight, false, SurfaceFormat::Color,
                                             DepthFormat::Depth24Stencil8);
    Scene->Name = "Scene";

    //Create Light Manager
    lightManager = std::make_unique<Lights::LightManager>(Content);

    //Load SpotLight Cookies
    Texture2D* spotCookie = Content.Load<Texture2D>("SpotCookie");
    Texture2D* squareCookie = Content.Load<Texture2D>("SquareCookie");
    (void)squareCookie;

    //Add a Directional Light
    lightManager->AddLight(std::make_unique<Lights::DirectionalLight>(Vector3::Down, Color::White, 0.05f));

    //Add a Spot Light
    lightManager->AddLight(std::make_unique<Lights::SpotLight>(*GraphicsDevice, Vector3(0, 15.0f, 0), Vector3(0, -1, 0),
                                                               Color::White.ToVector4(), 0.10f, true, 2048, spotCookie));

    //Add a Point Light
    lightManager->AddLight(std::make_unique<Lights::PointLight>(*GraphicsDevice, Vector3(0, 5.0f, 0), 20.0f,
                                                                Color::White.ToVector4(), 0.80f, true, 256));

    //Initialize Model List
    models = std::vector<Model*>();

    //Load Models
    Model* scene = Content.Load<Model>("Scene");
    models.push_back(scene);

    // fxport: the demo's starting values (see DemoSettings).
    ssao->setSampleRadius(demo.sampleRadius);
    ssao->setDistanceScale(demo.distanceScale);
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
    ssao->Modify(currentK);

    Game::Update(gameTime);
}

void Game1::Draw(const GameTime& gameTime) {
    //Clear
    GraphicsDevice->Clear(Color::CornflowerBlue);

    //Draw Shadow Maps
    { PassTimer timed(demo.gpuTimer, "ShadowMaps"); lightManager->DrawShadowMaps(*GraphicsDevice, models); }

    //Draw with SSAO unless F1 is down
    if (currentK.IsKeyDown(Keys::F1)) {
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
        ssao->Debug(*spriteBatch, *spriteFont);
    }

    //Base Drawing
    Game::Draw(gameTime);
}

}  // namespace TheCansinDeferredRenderer
