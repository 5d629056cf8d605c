// Rabid Lion's 2D lighting (seed 002): ray count (the unwrap / occlusion-map width), the occlusion
// targets' precision and the blur radius. The scene is the demo's kind (tiled background, boxes,
// discs, an "L"; point and spot lights), drawn through the seed's LightRenderer. Reference: the
// exact image by marching the shadow-caster bitmap on the CPU (lighting2d_reference.h).
//
// The point lights sit on the vertical centre line: Unwrap.fx as the seed writes it swaps the two
// half-planes' ray lengths (demo/lighting2d/README.md), which for lights off that line puts an
// error into every setting that no knob changes.
#include <cmath>
#include <memory>

#include "fxport/framework.h"
#include "lighting2d/light_renderer.h"
#include "lighting2d/scene_sprites.h"
#include "report/lighting2d_reference.h"
#include "report/sweep.h"

namespace fxport::report {

namespace {

using namespace _2DLightingSystem;

struct Knobs {
    int rayCount = 0;  // 0: the screen width
    SurfaceFormat occlusionFormat = SurfaceFormat::HdrBlendable;
    float maxBlur = 5.0f;
};


class Scene2D : public fxport::Game {
public:
    explicit Scene2D(const Knobs& knobs) : knobs_(knobs) {
        Content.RootDirectory = FXPORT_CONTENT_DIR;
        Content.EffectDirectory = FXPORT_HLSL_DIR "/lighting2d";
    }
    std::unique_ptr<LightRenderer> lightRenderer;
    GpuTimer* gpuTimer = nullptr;

protected:
    void Initialize() override {
        lightRenderer = std::make_unique<LightRenderer>(graphics, *GraphicsDevice);
        lightRenderer->rayCount = knobs_.rayCount;
        lightRenderer->occlusionFormat = knobs_.occlusionFormat;
        lightRenderer->maxBlur = knobs_.maxBlur;
        lightRenderer->Initialize();
        lightRenderer->lightBias = 3.f;
        lightRenderer->minLight = 0.15f;
        const float W = float(GraphicsDevice->Viewport.Width), H = float(GraphicsDevice->Viewport.Height);
        auto at = [&](float fx, float fy) { return Vector2(std::round(fx * W), std::round(fy * H)); };
        const float R = 0.7f * W, deg = MathHelper::Pi / 180.f;
        lightRenderer->pointLights.emplace_back(at(0.5f, 0.30f), 1.0f, R * 0.8f, Color(255, 140, 60));
        lightRenderer->pointLights.emplace_back(at(0.5f, 0.78f), 1.0f, R * 0.6f, Color(80, 160, 255));
        lightRenderer->spotLights.emplace_back(at(0.30f, 0.04f), Vector2(0, 1), 30 * deg, 60 * deg, 1.2f, R,
                                               Color(255, 255, 200));
        lightRenderer->spotLights.emplace_back(at(0.03f, 0.92f), Vector2::Normalize(Vector2(1, -0.6f)), 25 * deg,
                                               50 * deg, 1.0f, R, Color(255, 230, 90));
        Game::Initialize();
    }

    void LoadContent() override {
        spriteBatch_ = std::make_unique<SpriteBatch>(*GraphicsDevice);
        lightRenderer->LoadContent(Content);
        _2DLightingSystem::SceneSprites sprites = _2DLightingSystem::MakeSceneSprites(*GraphicsDevice);
        background_ = std::move(sprites.background);
        box_ = std::move(sprites.box);
        disc_ = std::move(sprites.disc);
        bar_ = std::move(sprites.bar);
    }

    void Draw(const fxport::GameTime&) override {
        const int W = GraphicsDevice->Viewport.Width, H = GraphicsDevice->Viewport.Height;
        {
            demo::PassTimer t(gpuTimer, "Background");
            lightRenderer->BeginDrawBackground();
            spriteBatch_->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointWrap, nullptr, nullptr);
            spriteBatch_->Draw(*background_, Vector2(0, 0), Rectangle(0, 0, W, H), Color::White);
            spriteBatch_->End();
            lightRenderer->EndDrawBackground();
        }
        {
            demo::PassTimer t(gpuTimer, "ShadowCasters");
            lightRenderer->BeginDrawShadowCasters();
            // Point sampling: the casters' texels are the reference's input as drawn.
            spriteBatch_->Begin(SpriteSortMode::Deferred, BlendState::AlphaBlend, SamplerState::PointClamp, nullptr, nullptr);
            auto px = [&](float f, int size) { return int(std::round(f * float(size))); };
            spriteBatch_->Draw(*box_, Rectangle(px(0.35f, W), px(0.40f, H), W / 12, W / 12), Color::White);
            spriteBatch_->Draw(*box_, Rectangle(px(0.62f, W), px(0.25f, H), W / 20, H / 3), Color::White);
            spriteBatch_->Draw(*disc_, Rectangle(px(0.15f, W), px(0.55f, H), W / 10, W / 10), Color::White);
            spriteBatch_->Draw(*disc_, Rectangle(px(0.44f, W), px(0.12f, H), W / 16, W / 16), Color::White);
            spriteBatch_->Draw(*bar_, Rectangle(px(0.75f, W), px(0.60f, H), W / 24, H / 5), Color::White);
            spriteBatch_->End();
            lightRenderer->EndDrawShadowCasters();
        }
        lightRenderer->DrawLitScene();
    }

private:
    Knobs knobs_;
    std::unique_ptr<SpriteBatch> spriteBatch_;
    std::unique_ptr<Texture2D> background_, box_, disc_, bar_;
};

}  // namespace

std::vector<Measurement> sweepLighting2d(const SweepOptions& options) {
    const int width = options.width ? options.width : 800, height = options.height ? options.height : 480;
    struct Setting {
        std::string knob, setting;
        Knobs knobs;
        bool seed;
    };
    std::vector<Setting> settings;
    const std::vector<int> rays = options.quick ? std::vector<int>{32, 128} : std::vector<int>{128, 256, 512, 1024, 2048};
    for (int r : rays) settings.push_back({"ray count", std::to_string(r), {r, SurfaceFormat::HdrBlendable, 5.0f}, false});
    settings.push_back({"ray count", std::to_string(width) + " (screen width)", {0, SurfaceFormat::HdrBlendable, 5.0f}, true});
    settings.push_back({"occlusion format", "HdrBlendable", {0, SurfaceFormat::HdrBlendable, 5.0f}, true});
    settings.push_back({"occlusion format", "Color", {0, SurfaceFormat::Color, 5.0f}, false});
    const std::vector<float> blurs = options.quick ? std::vector<float>{0.f, 5.f} : std::vector<float>{0.f, 1.f, 2.5f, 5.f, 10.f};
    for (float b : blurs) {
        char name[32];
        std::snprintf(name, sizeof name, "%g px", double(b));
        settings.push_back({"max blur", name, {0, SurfaceFormat::HdrBlendable, b}, b == 5.f});
    }

    std::vector<Measurement> out;
    for (const Setting& s : settings) {
        Scene2D game(s.knobs);
        game.graphics.PreferredBackBufferWidth = width;
        game.graphics.PreferredBackBufferHeight = height;
        game.graphics.platform = options.platform;
        game.Start();
        auto timer = std::make_unique<GpuTimer>(*game.GraphicsDevice);
        game.gpuTimer = timer.get();
        game.lightRenderer->gpuTimer = timer.get();
        Measurement m;
        m.demo = "lighting2d";
        m.knob = s.knob;
        m.setting = s.setting;
        m.seedDefault = s.seed;
        m.reference = "CPU bitmap marching (exact)";
        runTimedFrames(*game.GraphicsDevice, *timer, options, [&] { game.Tick(); }, m);
        const std::vector<Color> background = game.lightRenderer->backBufferCache->GetData<Color>();
        const std::vector<Color> casters = game.lightRenderer->midGroundTarget->GetData<Color>();
        const std::vector<double> reference = lighting2dReference(*game.lightRenderer, background, casters, width, height);
        m.error = compareImages(toRgb(game.GraphicsDevice->GetBackBufferData()), reference,
                                "lighting2d " + s.knob + " " + s.setting);
        if (out.empty()) saveReference(*game.GraphicsDevice, options, m.demo, reference, width, height);
        saveImage(*game.GraphicsDevice, options, m);
        game.lightRenderer->gpuTimer = nullptr;
        game.gpuTimer = nullptr;
        out.push_back(m);
        if (options.progress) options.progress(m);
    }
    return out;
}

}  // namespace fxport::report
