// fxdemo lighting2d: Rabid Lion Games' 2D lighting system with shadows (seed 002) on fxport.
//
//   fxdemo lighting2d [--size WxH] [--frames N] [--out DIR] [--gpu] [--window] [--check]
//                     [--lights sp] [--explain]
//
// Game1 draws a procedural background and a few opaque shadow-casting sprites through the
// LightRenderer's Begin/End pattern, with three point lights and three spot lights, then
// DrawLitScene(). Headless (OSMesa) by default: N frames (3), then DIR/final.png (the back buffer),
// DIR/debug.png (a sheet of the intermediate targets) and each of them in DIR/targets/, and the
// median GPU time of each step. --gpu: EGL; --window: GLFW (Escape quits). --check: compare every
// light's targets, the accumulated light map and the back buffer of the last frame with CPU
// references of the effects (reference_check.h); exit 1 if off. --lights: the light types drawn
// (s spot, p point; both by default). --explain: the effects (compile time), targets (bytes) and
// passes built and left out against the all-features scene (build_report.h).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "common/finite_check.h"
#include "common/frame_loop.h"
#include "fxport/framework.h"
#include "common/program_registry.h"
#include "common/run_options.h"
#include "fxport/framework/input.h"
#include "fxport/platform/graphics_context.h"
#include "lighting2d/build_report.h"
#include "lighting2d/light_renderer.h"
#include "lighting2d/reference_check.h"
#include "lighting2d/scene_sprites.h"

namespace _2DLightingSystem {

using fxport::GameTime;
using fxport::demo::PassTimer;

// Procedural sprites (fxport: the seed's textures are not available; made with SetData).

class Game1 : public fxport::Game {
public:
    std::unique_ptr<LightRenderer> lightRenderer;
    std::unique_ptr<SpriteBatch> spriteBatch;
    std::unique_ptr<Texture2D> background, box, disc, bar;

    // fxport: debug copies of the targets of the first spot light and the first point light.
    bool captureDebug = false;
    std::unique_ptr<RenderTarget2D> dbgSpotUnwrap, dbgSpotOcclusion, dbgSpotLightMap, dbgSpotBlurred;
    std::unique_ptr<RenderTarget2D> dbgPointUnwrap, dbgPointOcclusion, dbgPointLightMap, dbgPointBlurred;
    bool spotCaptured = false, pointCaptured = false;
    // fxport --check: every light of each frame (the last frame's are checked).
    CheckCapture* checkCapture = nullptr;
    // fxport --lights: the light types of the scene, set before Start().
    bool withSpotLights = true, withPointLights = true;

    Game1() {
        Content.RootDirectory = FXPORT_CONTENT_DIR;
        Content.EffectDirectory = FXPORT_HLSL_DIR "/lighting2d";
    }

protected:
    void Initialize() override {
        lightRenderer = std::make_unique<LightRenderer>(graphics, *GraphicsDevice);
        lightRenderer->Initialize();
        // The developer's settings the seed asks for.
        lightRenderer->lightBias = 3.f;
        lightRenderer->minLight = 0.15f;
        const float W = float(GraphicsDevice->Viewport.Width), H = float(GraphicsDevice->Viewport.Height);
        auto at = [&](float fx, float fy) { return Vector2(std::round(fx * W), std::round(fy * H)); };
        const float R = 0.7f * W;
        if (withPointLights) {
            lightRenderer->pointLights.emplace_back(at(0.22f, 0.30f), 1.0f, R * 0.8f, Color(255, 140, 60));
            lightRenderer->pointLights.emplace_back(at(0.72f, 0.62f), 1.0f, R * 0.7f, Color(80, 160, 255));
            lightRenderer->pointLights.emplace_back(at(0.50f, 0.90f), 0.8f, R * 0.5f, Color(120, 255, 120));
        }
        const float deg = MathHelper::Pi / 180.f;
        // Straight down (angle 0: sinTheta == 0 exactly in the middle column of the unwrap),
        // straight up (the port's Sign(0) case; angle PI), and a diagonal one.
        if (withSpotLights) {
            lightRenderer->spotLights.emplace_back(at(0.50f, 0.04f), Vector2(0, 1), 30 * deg, 60 * deg, 1.2f, R,
                                                   Color(255, 255, 200));
            lightRenderer->spotLights.emplace_back(at(0.88f, 0.95f), Vector2(0, -1), 20 * deg, 45 * deg, 1.0f, R,
                                                   Color(255, 80, 200));
            lightRenderer->spotLights.emplace_back(at(0.03f, 0.92f), Vector2::Normalize(Vector2(1, -0.6f)), 25 * deg,
                                                   50 * deg, 1.0f, R, Color(255, 230, 90));
        }
        Game::Initialize();
    }

    void LoadContent() override {
        spriteBatch = std::make_unique<SpriteBatch>(*GraphicsDevice);
        lightRenderer->LoadContent(Content);
        SceneSprites sprites = MakeSceneSprites(*GraphicsDevice);
        background = std::move(sprites.background);
        box = std::move(sprites.box);
        disc = std::move(sprites.disc);
        bar = std::move(sprites.bar);
        const int W = GraphicsDevice->Viewport.Width, H = GraphicsDevice->Viewport.Height;
        auto rt = [&](int w, int h, const char* name) {
            auto target = std::make_unique<RenderTarget2D>(*GraphicsDevice, w, h);
            target->Name = name;
            return target;
        };
        // Only for the light types the scene has (issue 6: nothing it does not need).
        if (!lightRenderer->spotLights.empty()) {
            dbgSpotUnwrap = rt(W, W, "debug.spotUnwrap"), dbgSpotOcclusion = rt(W, 48, "debug.spotOcclusion");
            dbgSpotLightMap = rt(W, H, "debug.spotLightMap"), dbgSpotBlurred = rt(W, H, "debug.spotBlurred");
        }
        if (!lightRenderer->pointLights.empty()) {
            dbgPointUnwrap = rt(W, W, "debug.pointUnwrap"), dbgPointOcclusion = rt(W, 48, "debug.pointOcclusion");
            dbgPointLightMap = rt(W, H, "debug.pointLightMap"), dbgPointBlurred = rt(W, H, "debug.pointBlurred");
        }
        lightRenderer->afterLightUser = this;
        lightRenderer->afterLight = [](LightRenderer& r, const Light& light, bool isSpot, void* user) {
            auto& g = *static_cast<Game1*>(user);
            if (g.checkCapture) {
                g.checkCapture->lights.emplace_back();
                CaptureLight(r, light, isSpot, g.checkCapture->lights.back());
            }
            if (!g.captureDebug || (isSpot ? g.spotCaptured : g.pointCaptured)) return;
            if (!(isSpot ? g.dbgSpotUnwrap : g.dbgPointUnwrap)) return;  // a light added after LoadContent
            (isSpot ? g.spotCaptured : g.pointCaptured) = true;
            g.copy(*r.unwrapTarget, isSpot ? *g.dbgSpotUnwrap : *g.dbgPointUnwrap);
            g.copy(*r.occlusionMap, isSpot ? *g.dbgSpotOcclusion : *g.dbgPointOcclusion);
            g.copy(*r.postProcessTarget, isSpot ? *g.dbgSpotLightMap : *g.dbgPointLightMap);
            g.copy(*r.verticalBlurTarget, isSpot ? *g.dbgSpotBlurred : *g.dbgPointBlurred);
        };
    }

    void Update(const GameTime&) override {
        if (Keyboard::GetState().IsKeyDown(Keys::Escape)) Exit();
    }

    void Draw(const GameTime&) override {
        const int W = GraphicsDevice->Viewport.Width, H = GraphicsDevice->Viewport.Height;
        spotCaptured = pointCaptured = false;
        if (checkCapture) checkCapture->lights.clear();
        {
            PassTimer t(gpuTimer, "Background");
            lightRenderer->BeginDrawBackground();
            spriteBatch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointWrap, nullptr, nullptr);
            spriteBatch->Draw(*background, Vector2(0, 0), Rectangle(0, 0, W, H), Color::White);
            spriteBatch->End();
            lightRenderer->EndDrawBackground();
        }
        {
            PassTimer t(gpuTimer, "ShadowCasters");
            lightRenderer->BeginDrawShadowCasters();
            spriteBatch->Begin();
            auto px = [&](float fx, float fy) { return Vector2(std::round(fx * W), std::round(fy * H)); };
            spriteBatch->Draw(*box, Rectangle(int(px(0.35f, 0).X), int(px(0, 0.35f).Y), W / 12, W / 12), Color::White);
            spriteBatch->Draw(*box, Rectangle(int(px(0.60f, 0).X), int(px(0, 0.25f).Y), W / 20, H / 3), Color::White);
            spriteBatch->Draw(*disc, Rectangle(int(px(0.15f, 0).X), int(px(0, 0.55f).Y), W / 10, W / 10), Color::White);
            spriteBatch->Draw(*disc, Rectangle(int(px(0.82f, 0).X), int(px(0, 0.30f).Y), W / 16, W / 16), Color::White);
            spriteBatch->Draw(*bar, Rectangle(int(px(0.45f, 0).X), int(px(0, 0.62f).Y), W / 24, H / 5), Color::White);
            spriteBatch->End();
            lightRenderer->EndDrawShadowCasters();
        }
        lightRenderer->DrawLitScene();
    }

public:
    GpuTimer* gpuTimer = nullptr;

    // --explain: the renderer's build and this program's debug copies.
    BuildReport Report(const GpuTimer* timer) {
        BuildReport report = ReportBuild(Content, *lightRenderer, timer);
        for (const auto* t : {&dbgSpotUnwrap, &dbgSpotOcclusion, &dbgSpotLightMap, &dbgSpotBlurred, &dbgPointUnwrap,
                              &dbgPointOcclusion, &dbgPointLightMap, &dbgPointBlurred})
            if (*t) report.addTarget(**t);
        return report;
    }

    // Leaves `to` bound: setting the light's target again would clear it (DiscardContents, as XNA
    // does), and the next step sets its own target anyway.
    void copy(Texture2D& from, RenderTarget2D& to) {
        GraphicsDevice->SetRenderTarget(to);
        spriteBatch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
        spriteBatch->Draw(from, Rectangle(0, 0, to.Width(), to.Height()), Color::White);
        spriteBatch->End();
    }

    // A sheet of the intermediate targets, 4 x 3 tiles of W/2 x H/2, saved with SaveAsPng.
    void WriteDebug(const std::string& dir) {
        const int W = GraphicsDevice->Viewport.Width, H = GraphicsDevice->Viewport.Height;
        const int tw = W / 2, th = H / 2;
        RenderTarget2D sheet(*GraphicsDevice, tw * 4, th * 3);
        Texture2D* tiles[] = {lightRenderer->backBufferCache.get(), lightRenderer->midGroundTarget.get(),
                              lightRenderer->lightMap.get(),        nullptr,
                              dbgSpotUnwrap.get(),  dbgSpotOcclusion.get(),  dbgSpotLightMap.get(),  dbgSpotBlurred.get(),
                              dbgPointUnwrap.get(), dbgPointOcclusion.get(), dbgPointLightMap.get(), dbgPointBlurred.get()};
        GraphicsDevice->SetRenderTarget(sheet);
        GraphicsDevice->Clear(Color(40, 0, 40));
        spriteBatch->Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr);
        for (int i = 0; i < 12; ++i)
            if (tiles[i]) spriteBatch->Draw(*tiles[i], Rectangle((i % 4) * tw, (i / 4) * th, tw - 2, th - 2), Color::White);
        spriteBatch->End();
        GraphicsDevice->SetRenderTarget(nullptr);
        sheet.SaveAsPng((std::filesystem::path(dir) / "debug.png").string());
        const auto targets = std::filesystem::path(dir) / "targets";
        std::filesystem::create_directories(targets);
        auto save = [&](const auto& t, const char* name) {
            if (t) t->SaveAsPng((targets / name).string());
        };
        save(lightRenderer->backBufferCache, "background.png");
        save(lightRenderer->midGroundTarget, "casters.png");
        save(lightRenderer->lightMap, "lightmap_accumulated.png");
        save(dbgSpotUnwrap, "spot0_unwrap.png");
        save(dbgSpotOcclusion, "spot0_occlusion.png");
        save(dbgSpotLightMap, "spot0_lightmap.png");
        save(dbgSpotBlurred, "spot0_blurred.png");
        save(dbgPointUnwrap, "point0_unwrap.png");
        save(dbgPointOcclusion, "point0_occlusion.png");
        save(dbgPointLightMap, "point0_lightmap.png");
        save(dbgPointBlurred, "point0_blurred.png");
    }
};

static int usage(const std::string& message) { return fxport::demo::usageError("lighting2d", message); }

// --explain's yardstick: the seed's scene with both light types (3 spot, 3 point lights), at the
// same size, platform and renderer knobs, built and drawn once by the same code in this run.
static void ExplainAgainstAllFeatures(const Game1& game, const BuildReport& built) {
    // This game has its own device: the main run's --check-finite scan stays with the main run.
    fxport::FiniteCheck* const mainRunCheck = PassTimer::finiteCheck;
    PassTimer::finiteCheck = nullptr;
    BuildReport all;
    {
        Game1 everything;
        everything.graphics.PreferredBackBufferWidth = game.graphics.PreferredBackBufferWidth;
        everything.graphics.PreferredBackBufferHeight = game.graphics.PreferredBackBufferHeight;
        everything.graphics.platform = game.graphics.platform;
        everything.Content.effectOptions = game.Content.effectOptions;
        everything.Start();
        GpuTimer timer(*everything.GraphicsDevice);
        everything.gpuTimer = &timer;
        everything.lightRenderer->gpuTimer = &timer;
        everything.captureDebug = true;  // as the main run's last frame
        everything.Tick();
        timer.EndFrame();
        timer.Finish();
        all = everything.Report(&timer);
        everything.gpuTimer = nullptr;
        everything.lightRenderer->gpuTimer = nullptr;
    }
    PassTimer::finiteCheck = mainRunCheck;
    fxport::demo::PrintExplain(stdout, built, all, "the seed's scene: 3 spot and 3 point lights; same size and platform");
    std::printf("lights drawn: %d spot, %d point (all-features: %d spot, %d point); the passes run once per light\n",
                built.spotLights, built.pointLights, all.spotLights, all.pointLights);
}

int runLighting2d(int argc, char** argv) {
    fxport::demo::CommonOptions common;
    common.width = 800;
    common.height = 480;
    common.outDir = "out/lighting2d";
    bool check = false;
    bool explain = false;
    bool lightScissor = true;
    std::string lights = "sp";
    for (int i = 1; i < argc; ++i) {
        std::string error;
        if (std::string(argv[i]) == "--check") {
            check = true;
            continue;
        }
        if (std::string(argv[i]) == "--explain") {
            explain = true;
            continue;
        }
        if (std::string(argv[i]) == "--no-light-scissor") {
            lightScissor = false;
            continue;
        }
        if (std::string(argv[i]) == "--lights") {
            const char* v = i + 1 < argc ? argv[++i] : nullptr;
            lights = v ? v : "";
            if (lights.empty() || lights.find_first_not_of("sp") != std::string::npos)
                return usage(fxport::demo::wants("--lights", "the letters s (spot) and p (point)", v));
            continue;
        }
        switch (fxport::demo::parseCommonOption(argc, argv, i, common, error)) {
        case fxport::demo::OptionResult::Consumed: continue;
        case fxport::demo::OptionResult::Error: return usage(error);
        case fxport::demo::OptionResult::NotMine: return usage(fxport::demo::unknownOption("lighting2d", argv[i]));
        }
    }
    if (std::string error; !fxport::demo::checkCommonOptions(common, error)) return usage(error);
    const int width = common.width, height = common.height, frames = common.frames.value_or(0);
    const std::string outDir = common.outDir, platformName = common.platform;
    const bool outGiven = common.outDirGiven;

    Game1 game;
    game.graphics.PreferredBackBufferWidth = width;
    game.graphics.PreferredBackBufferHeight = height;
    game.graphics.platform = platformName;
    game.withSpotLights = lights.find('s') != std::string::npos;
    game.withPointLights = lights.find('p') != std::string::npos;
    // --explain: every effect compiled by xlate in this process, so that the load times compare.
    if (explain) game.Content.effectOptions.useCache = false;
    game.Content.effectOptions.defines = common.defines;
    game.Start();
    game.lightRenderer->scissorLights = lightScissor;
    auto timer = std::make_unique<GpuTimer>(*game.GraphicsDevice);
    game.gpuTimer = timer.get();
    game.lightRenderer->gpuTimer = timer.get();
    CheckCapture checkCapture;
    if (check) game.checkCapture = &checkCapture;
    const bool sync = platformName == "osmesa";
    PassTimer::syncDevice = sync ? game.GraphicsDevice : nullptr;
    fxport::demo::PassBound::setUp(*game.GraphicsDevice, common.fillRateGBps, common.bounds);
    fxport::demo::FiniteCheckScope finite(game.GraphicsDevice, common.checkFinite);
    std::printf("fxdemo lighting2d: %dx%d on %s (%s); %zu spot lights, %zu point lights\n", width, height,
                platformName.c_str(), game.GraphicsDevice->rendererName().c_str(),
                game.lightRenderer->spotLights.size(), game.lightRenderer->pointLights.size());

    const bool windowed = platformName == "glfw";
    fxport::demo::runFrameLoop(*game.GraphicsDevice, *timer, windowed, frames ? std::optional<int>(frames) : std::nullopt, 3,
                 [&](int, bool lastHeadless) {
                     if (game.ExitRequested()) return false;
                     // Headless, the debug copies are made in the last frame only (they are not
                     // timed frames' work); in a window in every frame when --out asks for them.
                     game.captureDebug = windowed ? outGiven : lastHeadless;
                     game.Tick();
                     return true;
                 });
    PassTimer::syncDevice = nullptr;
    fxport::demo::PassBound::device = nullptr;
    std::printf("%d frames; median GPU time per pass (per light for the per-light steps; frame = the whole frame)%s:\n", game.FrameCount(),
                sync ? " (each pass finished before and after)" : "");
    for (const GpuTimer::Section& section : timer->Sections())
        std::printf("  %-14s %9.3f ms%s\n", section.name.c_str(), section.medianMs(),
                    fxport::demo::PassBound::columns(section).c_str());

    // Before the images: the check reads the back buffer.
    int status = 0;
    if (check && !CheckLighting(*game.lightRenderer, checkCapture)) status = 1;
    if (platformName != "glfw" || outGiven) {
        std::filesystem::create_directories(outDir);
        const std::string finalPath = (std::filesystem::path(outDir) / "final.png").string();
        game.GraphicsDevice->SaveBackBufferAsPng(finalPath);
        game.WriteDebug(outDir);
        std::printf("wrote %s, %s/debug.png and %s/targets/*.png\n", finalPath.c_str(), outDir.c_str(), outDir.c_str());
    }
    if (explain) ExplainAgainstAllFeatures(game, game.Report(timer.get()));
    return status;
}

}  // namespace _2DLightingSystem

FXDEMO_PROGRAM(lighting2d,
               "fxdemo lighting2d [--size WxH] [--frames N] [--out DIR] [--gpu] [--window] [--check] [--lights sp]\n"
               "                         [--explain] [--no-light-scissor]\n"
               "  Rabid Lion Games' 2D lighting system (seed 002): writes DIR/final.png and DIR/debug.png.\n"
               "  --size WxH     back buffer size (800x480)      --frames N   frames to run headless\n"
               "  --out DIR      where the images go (out/lighting2d)\n"
               "  --check        compare every light's steps, the light map and the frame with CPU references\n"
               "  --lights sp    keep only the spot (s) and/or point (p) lights\n"
               "  --explain      print the effects, targets and passes built and left out\n"
               "  --no-light-scissor  draw each light's light map, blurs and accumulation over the whole\n"
               "                 screen (default: scissored to the light's reach; the same image)",
               _2DLightingSystem::runLighting2d);
