// `fxdemo pointlights`: runs the port of Catalin Zima's "Point Lights" chapter (seed 001) headless
// for a number of frames, or in a window, and writes what it rendered: DIR/final.png (the frame)
// and DIR/debug.png (G-buffer targets and light map), and prints the median GPU time of each pass.
//   --time T   draw every frame at game time T (the lights' animation), so a frame is reproducible
//   --gpu      headless on the GPU (EGL); --window: a GLFW window (arrow keys orbit, W/S zoom,
//              Escape quits; images only with --out)
//   --check    compare the last frame's G-buffer, lightRT and back buffer with CPU references of the
//              passes (reference_check.h); exit 1 if off
//   --spot     also draw the chapter's exercise: one spot light (SpotLight.fx, cone volume)
//   --camera ARC,ROTATION,DISTANCE  the orbit camera's start (degrees, degrees, units; -25,0,20)
//   --gbuffer tutorial|half16|float32  the G-buffer's and lightRT's formats (the series' Color/Color/
//              Single with a Color light map; HalfVector4 x2/HalfSingle; Vector4 x2/Single)
//   --light-count N  N point lights in the chapter's two rings (the report's knob; issue 16's 10 000)
//   --no-cull  draw every point light, also those outside the view frustum (as the chapter)
//   --explain  print the effects (compile time), targets (bytes) and passes built and left out,
//              and the point lights drawn and frustum-culled, against the all-features scene
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>

#include "common/finite_check.h"
#include "common/frame_loop.h"
#include "common/program_registry.h"
#include "common/run_options.h"
#include "fxport/platform/graphics_context.h"
#include "pointlights/build_report.h"
#include "pointlights/debug_sheet.h"
#include "pointlights/game1.h"
#include "pointlights/reference_check.h"

namespace DeferredLighting {

using fxport::demo::CommonOptions;
using fxport::demo::OptionResult;
using fxport::demo::parseCommonOption;

namespace {

const char* kUsage = "fxdemo pointlights [--size WxH] [--frames N] [--out DIR] [--time T] [--gpu] [--window]\n"
                     "                          [--spot] [--check] [--camera A,R,D] [--no-cull]\n"
                     "                          [--gbuffer tutorial|half16|float32] [--light-count N] [--explain]\n"
                     "  Catalin Zima's deferred point lights (seed 001): writes DIR/final.png and DIR/debug.png.\n"
                     "  --size WxH     back buffer size (800x600)      --frames N   frames to run headless\n"
                     "  --out DIR      where the images go (fxdemo-out/pointlights)\n"
                     "  --time T       game time in seconds of the first frame (the lights move with it)\n"
                     "  --spot         add the chapter's exercise, a spot light\n"
                     "  --check        compare the G-buffer, light map and frame with CPU references\n"
                     "  --camera A,R,D the camera's arc, rotation (degrees) and distance\n"
                     "  --no-cull      draw every light, also those outside the view frustum\n"
                     "  --gbuffer F    the G-buffer's formats: tutorial (Color, Color, Single), half16, float32\n"
                     "  --light-count N  N point lights (1..100000) in the chapter's two rings instead of its 22\n"
                     "  --explain      print the effects, targets and passes built and left out";

int usage(const std::string& message) { return fxport::demo::usageError("pointlights", message); }

}  // namespace

int runPointLights(int argc, char** argv) {
    CommonOptions common;
    common.outDir = "fxdemo-out/pointlights";
    std::optional<double> time;
    bool spot = false;
    bool check = false;
    bool explain = false;
    bool cull = true;
    bool cameraGiven = false;
    int lightCount = 0;
    GBufferFormats formats = GBufferFormats::Tutorial;
    float cameraArc = 0, cameraRotation = 0, cameraDistance = 0;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
        std::string error;
        OptionResult parsed = parseCommonOption(argc, argv, i, common, error);
        if (parsed == OptionResult::Error) return usage(error);
        if (parsed == OptionResult::Consumed) continue;
        if (arg == "--time") {
            const char* v = value();
            char* end = nullptr;
            if (!v) return usage(fxport::demo::wants("--time", "seconds", v));
            double t = std::strtod(v, &end);
            if (end == v || *end || !std::isfinite(t)) return usage(fxport::demo::wants("--time", "seconds", v));
            time = t;
        } else if (arg == "--check") {
            check = true;
        } else if (arg == "--spot") {
            spot = true;
        } else if (arg == "--explain") {
            explain = true;
        } else if (arg == "--gbuffer") {
            const char* v = value();
            const std::string name = v ? v : "";
            if (name == "tutorial") formats = GBufferFormats::Tutorial;
            else if (name == "half16") formats = GBufferFormats::Half16;
            else if (name == "float32") formats = GBufferFormats::Float32;
            else return usage(fxport::demo::wants("--gbuffer", "tutorial, half16 or float32", v));
        } else if (arg == "--light-count") {
            const char* v = value();
            char* end = nullptr;
            const long n = v ? std::strtol(v, &end, 10) : 0;
            if (!v || *end || n < 1 || n > 100000) return usage(fxport::demo::wants("--light-count", "a number of lights from 1 to 100000", v));
            lightCount = int(n);
        } else if (arg == "--no-cull") {
            cull = false;
        } else if (arg == "--camera") {
            const char* v = value();
            if (!v || std::sscanf(v, "%f,%f,%f", &cameraArc, &cameraRotation, &cameraDistance) != 3 ||
                !(cameraDistance > 0))
                return usage(fxport::demo::wants("--camera", "ARC,ROTATION,DISTANCE (degrees, degrees, units > 0)", v));
            cameraGiven = true;
        } else {
            return usage(fxport::demo::unknownOption("pointlights", arg));
        }
    }
    if (std::string error; !fxport::demo::checkCommonOptions(common, error)) return usage(error);

    if (check && formats != GBufferFormats::Tutorial)
        return usage("--check models the series' Color/Color/Single targets only: leave out --gbuffer");
    // The check recomputes the spot light from the frame's game time: it needs a fixed one.
    if (check && spot && !time && common.platform == "glfw") return usage("--check --spot in a window wants --time T");

    Game1 game;
    game.graphics.PreferredBackBufferWidth = common.width;
    game.graphics.PreferredBackBufferHeight = common.height;
    game.graphics.platform = common.platform;
    // Headless without --time: a fixed time, so that the default run is reproducible too.
    game.demo.time = time ? time : (common.platform == "glfw" ? std::nullopt : std::optional<double>(1.0));
    game.demo.quality.gbufferFormats = formats;
    game.demo.quality.lightCount = lightCount;
    if (cameraGiven) {
        game.demo.cameraArc = cameraArc;
        game.demo.cameraRotation = cameraRotation;
        game.demo.cameraDistance = cameraDistance;
    }
    // --explain: every effect compiled by xlate in this process, so that the load times compare.
    if (explain) game.Content.effectOptions.useCache = false;
    game.Content.effectOptions.defines = common.defines;

    game.Start();
    game.getRenderer().drawSpotLight = spot;
    game.getRenderer().frustumCulling = cull;
    auto timer = std::make_unique<GpuTimer>(*game.GraphicsDevice);
    game.getRenderer().setGpuTimer(timer.get());
    const bool sync = common.platform == "osmesa";
    PassTimer::syncDevice = sync ? game.GraphicsDevice : nullptr;
    fxport::demo::PassBound::setUp(*game.GraphicsDevice, common.fillRateGBps, common.bounds);
    fxport::demo::FiniteCheckScope finite(game.GraphicsDevice, common.checkFinite);

    const Camera& camera = game.getCamera();
    std::printf("fxdemo pointlights: %dx%d on %s (%s)\n", common.width, common.height, common.platform.c_str(),
                game.GraphicsDevice->rendererName().c_str());
    std::printf("1 directional + %d point lights; camera (%.2f, %.2f, %.2f); light rig scale %.2f centre (%.1f, %.1f, %.1f); "
                "time %s\n",
                lightCount ? lightCount : 22, double(camera.Position.X), double(camera.Position.Y), double(camera.Position.Z),
                double(game.getRenderer().lightRig.scale), double(game.getRenderer().lightRig.center.X),
                double(game.getRenderer().lightRig.center.Y), double(game.getRenderer().lightRig.center.Z),
                game.demo.time ? std::to_string(*game.demo.time).c_str() : "game clock");

    fxport::demo::runFrameLoop(*game.GraphicsDevice, *timer, common.platform == "glfw", common.frames, 3, [&](int, bool) {
        if (game.ExitRequested()) return false;
        game.Tick();
        return true;
    });
    PassTimer::syncDevice = nullptr;
    fxport::demo::PassBound::device = nullptr;

    std::printf("last frame: %d point lights drawn with CullClockwise (camera inside: inner faces), %d with "
                "CullCounterClockwise, %d outside the view frustum not drawn\n",
                game.getRenderer().insideLights, game.getRenderer().outsideLights, game.getRenderer().culledLights);
    if (spot)
        std::printf("spot light drawn with %s\n", game.getRenderer().spotInside ? "CullClockwise (camera inside)"
                                                                                 : "CullCounterClockwise");
    std::printf("%d frames; median GPU time per pass%s:\n", game.FrameCount(),
                sync ? " (each pass finished before and after)" : "");
    for (const GpuTimer::Section& section : timer->Sections())
        std::printf("  %-16s %9.3f ms%s\n", section.name.c_str(), section.medianMs(),
                    fxport::demo::PassBound::columns(section).c_str());

    int status = 0;
    if (check && !CheckPasses(game, spot, game.demo.time.value_or(0.0))) status = 1;

    if (common.platform != "glfw" || common.outDirGiven) {
        std::filesystem::create_directories(common.outDir);
        const std::string finalPath = (std::filesystem::path(common.outDir) / "final.png").string();
        const std::string debugPath = (std::filesystem::path(common.outDir) / "debug.png").string();
        game.GraphicsDevice->SaveBackBufferAsPng(finalPath);
        WriteDebugSheet(game, debugPath);
        std::printf("wrote %s and %s\n", finalPath.c_str(), debugPath.c_str());
    }
    if (explain) ExplainAgainstAllFeatures(stdout, game, ReportBuild(game, timer.get()));
    return status;
}

}  // namespace DeferredLighting

FXDEMO_PROGRAM(pointlights, DeferredLighting::kUsage, DeferredLighting::runPointLights);
