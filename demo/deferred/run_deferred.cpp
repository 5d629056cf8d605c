#include "deferred/run_deferred.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "common/finite_check.h"
#include "common/frame_loop.h"
#include "common/program_registry.h"
#include "common/run_options.h"
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
    game.demo.reuseShadowMaps = options.reuseShadowMaps;
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
    fxport::demo::PassBound::setUp(*game.GraphicsDevice, options.fillRateGBps, options.bounds);
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
    fxport::demo::PassBound::device = nullptr;
    std::printf("%d frames; median GPU time per pass%s:\n", game.FrameCount(),
                sync ? " (each pass finished before and after: --sync-passes)" : "");
    for (const GpuTimer::Section& section : timer->Sections())
        std::printf("  %-12s %9.3f ms%s\n", section.name.c_str(), section.medianMs(),
                    fxport::demo::PassBound::columns(section).c_str());

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

namespace {

int usage(const std::string& message) { return fxport::demo::usageError("deferred", message); }

bool parseFloats(const std::string& text, std::vector<float>& out, std::size_t count) {
    out.clear();
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        try {
            std::size_t used = 0;
            out.push_back(std::stof(item, &used));
            if (used != item.size()) return false;
        } catch (const std::exception&) {
            return false;
        }
    }
    return out.size() == count;
}

}  // namespace

int RunDeferredProgram(int argc, char** argv) {
    using fxport::demo::wants;
    RunOptions options;
    // The options every program shares (--size, --frames, --out, --gpu, --window, --check-finite,
    // --define) are parsed by common/run_options, as the other programs do.
    fxport::demo::CommonOptions common;
    common.width = options.width;
    common.height = options.height;
    common.outDir = options.outDir;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
        std::string error;
        const fxport::demo::OptionResult parsed = fxport::demo::parseCommonOption(argc, argv, i, common, error);
        if (parsed == fxport::demo::OptionResult::Error) return usage(error);
        if (parsed == fxport::demo::OptionResult::Consumed) continue;
        if (arg == "--camera") {
            const char* v = value();
            std::vector<float> f;
            if (!v || !parseFloats(v, f, 6)) return usage(wants("--camera", "PX,PY,PZ,TX,TY,TZ", v));
            options.cameraPosition = fxport::Vector3(f[0], f[1], f[2]);
            options.cameraTarget = fxport::Vector3(f[3], f[4], f[5]);
        } else if (arg == "--ssao") {
            const char* v = value();
            std::vector<float> f;
            if (!v || !parseFloats(v, f, 2)) return usage(wants("--ssao", "RADIUS,SCALE", v));
            options.sampleRadius = f[0];
            options.distanceScale = f[1];
        } else if (arg == "--lights") {
            const char* v = value();
            if (!v || !*v || std::string(v).find_first_not_of("dsp") != std::string::npos)
                return usage(wants("--lights", "letters of d (directional), s (spot), p (point)", v));
            options.lights = v;
        } else if (arg == "--no-debug-views") {
            options.debugViews = false;
        } else if (arg == "--sync-passes") {
            options.syncPasses = true;
        } else if (arg == "--no-sync-passes") {
            options.syncPasses = false;
        } else if (arg == "--gbuffer") {
            using Formats = Game1::DemoSettings::GBufferFormats;
            const char* v = value();
            const std::string name = v ? v : "";
            if (name == "tutorial") options.gbufferFormats = Formats::Tutorial;
            else if (name == "color8") options.gbufferFormats = Formats::Color8;
            else if (name == "float32") options.gbufferFormats = Formats::Float32;
            else return usage(wants("--gbuffer", "tutorial, color8 or float32", v));
        } else if (arg == "--spot-shadow" || arg == "--point-shadow") {
            const char* v = value();
            const bool spot = arg == "--spot-shadow";
            const int lo = spot ? 256 : 64, hi = spot ? 4096 : 1024;
            char* end = nullptr;
            const long n = v ? std::strtol(v, &end, 10) : 0;
            if (!v || *end || n < lo || n > hi)
                return usage(wants(arg, "a size in " + std::to_string(lo) + ".." + std::to_string(hi), v));
            (spot ? options.spotShadowMapSize : options.pointShadowMapSize) = int(n);
        } else if (arg == "--no-ssao") {
            options.ssao = false;
        } else if (arg == "--ssao-half") {
            options.ssaoHalfResolution = true;
        } else if (arg == "--no-shadow-cache") {
            options.reuseShadowMaps = false;
        } else if (arg == "--explain") {
            options.explain = true;
        } else if (arg == "--targets") {
            options.fullSizeImages = true;
        } else if (arg == "--content") {
            const char* v = value();
            if (!v) return usage(wants("--content", "a folder", v));
            options.contentDir = v;
        } else if (arg == "--hlsl") {
            const char* v = value();
            if (!v) return usage(wants("--hlsl", "a folder", v));
            options.hlslDir = v;
        } else {
            return usage(fxport::demo::unknownOption("deferred", arg));
        }
    }
    if (std::string error; !fxport::demo::checkCommonOptions(common, error)) return usage(error);

    options.width = common.width;
    options.height = common.height;
    options.frames = common.frames;
    options.outDir = common.outDir;
    options.outDirGiven = common.outDirGiven;
    options.platform = common.platform;
    options.checkFinite = common.checkFinite;
    options.fillRateGBps = common.fillRateGBps;
    options.bounds = common.bounds;
    options.defines = common.defines;
    return RunDeferred(options);
}

}  // namespace TheCansinDeferredRenderer

FXDEMO_PROGRAM(deferred,
               "fxdemo deferred [--size WxH] [--frames N] [--out DIR] [--gpu] [--window]\n"
               "                       [--camera PX,PY,PZ,TX,TY,TZ] [--ssao RADIUS,SCALE] [--lights dsp]\n"
               "                       [--no-debug-views] [--targets] [--[no-]sync-passes] [--content DIR] [--hlsl DIR]\n"
               "                       [--gbuffer tutorial|color8|float32] [--spot-shadow N] [--point-shadow N]\n"
               "                       [--no-ssao] [--ssao-half] [--no-shadow-cache] [--explain]\n"
               "  \"Deferred Rendering in XNA 4\" (seed 000), the last chapter: writes DIR/final.png and DIR/debug.png.\n"
               "  (final.png: the back buffer; debug.png: every intermediate target; prints each pass's GPU time.)\n"
               "  --size WxH      back buffer size (800x600)      --frames N   frames to run headless (3)\n"
               "  --out DIR       where the images go (fxdemo-out); in a window, images only with --out\n"
               "  --gpu           headless on the GPU (EGL)       --window     a GLFW window with the FreeCamera\n"
               "  --camera ...    camera position and target      --ssao R,S   SSAO sample radius and distance scale\n"
               "  --lights dsp    keep only some of the seed's lights: directional, spot, point\n"
               "  --no-debug-views  without the seed's Debug() views over the final image\n"
               "  --targets       every debug-sheet tile also at full size in DIR/targets/\n"
               "  --[no-]sync-passes  finish the device around each timed pass (default on OSMesa)\n"
               "  --content DIR / --hlsl DIR  the content and effect folders\n"
               "  --gbuffer F     the G-buffer's formats: tutorial (Rgba64, Rgba64, Vector2), color8, float32\n"
               "  --spot-shadow N (256..4096, 2048) / --point-shadow N (64..1024, 256): shadow map sizes\n"
               "  --no-ssao / --ssao-half  no SSAO / SSAO and its blur at half size\n"
               "  --no-shadow-cache  redraw every shadow map every frame (default: a map whose light and\n"
               "                  casters did not move is kept; the same image)\n"
               "  --explain       print the effects, targets (bytes) and passes built and left out",
               TheCansinDeferredRenderer::RunDeferredProgram);
