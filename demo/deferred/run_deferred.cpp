#include "deferred/run_deferred.h"

#include <cstdio>
#include <filesystem>

#include "common/finite_check.h"
#include "common/frame_loop.h"
#include "deferred/build_report.h"
#include "deferred/debug_sheet.h"
#include "deferred/game1.h"
#include "fxport/platform/graphics_context.h"

namespace TheCansinDeferredRenderer {

namespace {

// The options that shape the game, set before Start().
void Configure(Game1& game, const RunOptions& options) {
    game.graphics.PreferredBackBufferWidth = options.width;
    game.graphics.PreferredBackBufferHeight = options.height;
    game.graphics.platform = options.platform;
    if (!options.contentDir.empty()) game.Content.RootDirectory = options.contentDir;
    if (!options.hlslDir.empty()) game.Content.EffectDirectory = options.hlslDir + "/xna-deferred";
    game.demo.cameraPosition = options.cameraPosition;
    game.demo.cameraTarget = options.cameraTarget;
    game.demo.sampleRadius = options.sampleRadius;
    game.demo.distanceScale = options.distanceScale;
    game.demo.debugViews = options.debugViews;
    game.demo.gbufferFormats = options.gbufferFormats;
    game.demo.spotShadowMapSize = options.spotShadowMapSize;
    game.demo.pointShadowMapSize = options.pointShadowMapSize;
    game.demo.ssao = options.ssao;
    game.demo.ssaoHalfResolution = options.ssaoHalfResolution;
    // --explain: every effect compiled by xlate in this process, so that the load times compare.
    if (options.explain) game.Content.effectOptions.useCache = false;
    game.Content.effectOptions.defines = options.defines;
}

// --explain's yardstick: the seed's scene with every feature (all three lights with shadows, SSAO,
// no frustum culling) at the same size, camera and knobs, built and drawn once by the same code.
BuildReport ReportAllFeatures(const RunOptions& options) {
    // This game has its own device: the main run's --check-finite scan stays with the main run.
    FiniteCheck* const mainRunCheck = PassTimer::finiteCheck;
    PassTimer::finiteCheck = nullptr;
    Game1 game;
    Configure(game, options);
    game.demo.ssao = true;
    game.Start();
    game.getDeferredRenderer().frustumCulling = false;
    GpuTimer timer(*game.GraphicsDevice);
    game.getDeferredRenderer().setGpuTimer(&timer);
    game.getSSAO().setGpuTimer(&timer);
    game.demo.gpuTimer = &timer;
    game.Tick();
    timer.EndFrame();
    timer.Finish();
    BuildReport report = ReportBuild(game, &timer);
    game.demo.gpuTimer = nullptr;
    PassTimer::finiteCheck = mainRunCheck;
    return report;
}

}  // namespace

int RunDeferred(const RunOptions& options) {
    Game1 game;
    Configure(game, options);

    // The timer needs the device, which Start() makes: attach it after Start, before the first frame.
    game.Start();
    auto timer = std::make_unique<GpuTimer>(*game.GraphicsDevice);
    // --lights: drop some of the seed's lights (to look at one light's contribution alone).
    Lights::LightManager& lights = game.getLightManager();
    auto keep = [&](char c) { return options.lights.find(c) != std::string::npos; };
    while (!keep('d') && !lights.getDirectionalLights().empty()) lights.RemoveLight(lights.getDirectionalLights()[0].get());
    while (!keep('s') && !lights.getSpotLights().empty()) lights.RemoveLight(lights.getSpotLights()[0].get());
    while (!keep('p') && !lights.getPointLights().empty()) lights.RemoveLight(lights.getPointLights()[0].get());
    game.getDeferredRenderer().setGpuTimer(timer.get());
    if (game.hasSSAO()) game.getSSAO().setGpuTimer(timer.get());
    game.demo.gpuTimer = timer.get();
    const bool sync = options.syncPasses.value_or(options.platform == "osmesa");
    PassTimer::syncDevice = sync ? game.GraphicsDevice : nullptr;
    fxport::demo::FiniteCheckScope finite(game.GraphicsDevice, options.checkFinite);

    std::printf("fxdemo deferred: %dx%d on %s (%s)\n", options.width, options.height, options.platform.c_str(),
                game.GraphicsDevice->rendererName().c_str());
    std::printf("lights: %zu directional, %zu spot, %zu point; camera (%.2f, %.2f, %.2f) -> (%.2f, %.2f, %.2f); "
                "SSAO sample radius %.3f, distance scale %.3f\n",
                lights.getDirectionalLights().size(), lights.getSpotLights().size(), lights.getPointLights().size(),
                double(options.cameraPosition.X), double(options.cameraPosition.Y), double(options.cameraPosition.Z),
                double(options.cameraTarget.X), double(options.cameraTarget.Y), double(options.cameraTarget.Z),
                double(options.sampleRadius), double(options.distanceScale));

    // XNA's Run(): a window at 60 Hz until it closes, Escape or --frames; headless 3 frames.
    fxport::demo::runFrameLoop(*game.GraphicsDevice, *timer, options.platform == "glfw", options.frames, 3, [&](int, bool) {
        if (game.ExitRequested()) return false;
        game.Tick();
        return true;
    });

    PassTimer::syncDevice = nullptr;
    std::printf("%d frames; median GPU time per pass%s:\n", game.FrameCount(),
                sync ? " (each pass finished before and after: --sync-passes)" : "");
    for (const GpuTimer::Section& section : timer->Sections())
        std::printf("  %-12s %9.3f ms\n", section.name.c_str(), section.medianMs());

    if (options.platform != "glfw" || options.outDirGiven) {
        std::filesystem::create_directories(options.outDir);
        const std::string finalPath = (std::filesystem::path(options.outDir) / "final.png").string();
        const std::string debugPath = (std::filesystem::path(options.outDir) / "debug.png").string();
        game.GraphicsDevice->SaveBackBufferAsPng(finalPath);
        WriteDebugSheet(game, debugPath,
                        options.fullSizeImages ? (std::filesystem::path(options.outDir) / "targets").string() : "");
        std::printf("wrote %s and %s\n", finalPath.c_str(), debugPath.c_str());
    }

    if (options.explain) {
        const BuildReport built = ReportBuild(game, timer.get());
        PrintExplain(stdout, built, ReportAllFeatures(options));
    }
    return 0;
}

}  // namespace TheCansinDeferredRenderer
