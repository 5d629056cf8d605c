// Game1 (seed 000, chapter 6, the final chapter): the deferred renderer with a directional light,
// a shadowed spot light and a shadowed point light, followed by SSAO; the G-buffer and SSAO debug
// views on top. F1 held: no SSAO. Z/X and C/V change the SSAO sample radius and distance scale.
#pragma once

#include <memory>
#include <vector>

#include "deferred/Cameras/free_camera.h"
#include "deferred/Lights/light_manager.h"
#include "deferred/deferred_renderer.h"
#include "deferred/ssao.h"
#include "deferred/xna.h"

namespace TheCansinDeferredRenderer {

class Game1 : public Game {
    //SpriteBatch
    std::unique_ptr<SpriteBatch> spriteBatch;
    //Sprite Font
    SpriteFont* spriteFont = nullptr;
    std::unique_ptr<SpriteFont> debugFont;  // fxport: owns spriteFont
    //Keyboard State Holders
    KeyboardState currentK;
    KeyboardState previousK;
    //Mouse State Holder
    MouseState currentM;
    //Camera
    std::unique_ptr<FreeCamera> Camera;
    //Light Manager
    std::unique_ptr<Lights::LightManager> lightManager;
    //Deffered Renderer
    std::unique_ptr<DeferredRenderer> deferredRenderer;
    //SSAO
    std::unique_ptr<SSAO> ssao;
    //Scene
    std::unique_ptr<RenderTarget2D> Scene;
    //List of Models
    std::vector<Model*> models;

public:
    Game1();

    // fxport additions, for fxdemo: what it chooses before Start() and reads after the frames.
    struct DemoSettings {
        // The seed's camera starts at (0, 0, 5) looking at the origin; our Scene's floor is at
        // y = 0, so the demo's viewpoint is a setting (fxdemo --camera).
        Vector3 cameraPosition = Vector3(0.0f, 0.0f, 5.0f);
        Vector3 cameraTarget = Vector3(0.0f, 0.0f, 0.0f);
        // SSAO values a headless run starts with (the seed starts at 0, 0: no occlusion at all).
        float sampleRadius = 0.0f;
        float distanceScale = 0.0f;
        // Draw the seed's debug views (G-buffer, SSAO, values) over the final image.
        bool debugViews = true;
        // GPU time of ShadowMaps and Debug (nullptr: not measured); the other passes are timed by
        // DeferredRenderer/SSAO::setGpuTimer.
        GpuTimer* gpuTimer = nullptr;
        // Quality/cost knobs (issue 6; the seed's values are the defaults). Checked in LoadContent:
        // a value out of range throws ArgumentError naming the setting.
        // The G-buffer's three targets (albedo+spec intensity, normal+spec power, depth z/w + view z).
        // Color8's depth target is Single: it keeps z/w only, and SSAO reads view z (.g) from it,
        // so SSAO sees 0 there -- the knob shows what the tutorial's formats buy.
        enum class GBufferFormats { Tutorial /*Rgba64,Rgba64,Vector2*/, Color8 /*Color,Color,Single*/, Float32 /*Vector4 x3*/ };
        GBufferFormats gbufferFormats = GBufferFormats::Tutorial;
        int spotShadowMapSize = 2048;   // 256..4096 (the seed's spot light: 2048)
        int pointShadowMapSize = 256;   // cube face size, 64..1024 (the seed's point light: 256)
        bool ssao = true;               // false: no SSAO targets/effects at all (the image is the light composition)
        bool ssaoHalfResolution = false;  // SSAO and its blur at half the render size
        bool reuseShadowMaps = true;      // issue 16: LightManager::reuseShadowMaps (the same image)
    };
    DemoSettings demo;
    DeferredRenderer& getDeferredRenderer() { return *deferredRenderer; }
    // Without SSAO (demo.ssao false) there is no SSAO and no Scene target: getSSAO/getScene throw
    // InvalidOperation; hasSSAO says which.
    bool hasSSAO() const { return ssao != nullptr; }
    SSAO& getSSAO();
    Lights::LightManager& getLightManager() { return *lightManager; }
    const FreeCamera& getCamera() const { return *Camera; }
    RenderTarget2D& getScene();

protected:
    void Initialize() override;
    void LoadContent() override;
    void UnloadContent() override;
    void Update(const GameTime& gameTime) override;
    void Draw(const GameTime& gameTime) override;
};

}  // namespace TheCansinDeferredRenderer
