// fxdemo: the ported tutorial programs.
//
//   fxdemo deferred [--size WxH] [--frames N] [--out DIR] [--gpu] [--window]
//                   [--camera PX,PY,PZ,TX,TY,TZ] [--ssao RADIUS,SCALE] [--lights dsp]
//                   [--no-debug-views] [--targets] [--[no-]sync-passes] [--content DIR] [--hlsl DIR]
//
// deferred: "Deferred Rendering in XNA 4" (seed 000), the final chapter's Game1. Headless (OSMesa)
// by default: renders N frames (3), writes DIR/final.png (the back buffer) and DIR/debug.png (every
// intermediate target), and prints the median GPU time of each pass. --gpu: headless on the GPU
// (EGL). --window: a GLFW window with the FreeCamera (W/A/S/D/Q/E, left mouse button to turn, Z/X
// and C/V for SSAO, F1 without SSAO, Escape quits); images are written only with --out.
// --gbuffer: the G-buffer's formats (tutorial: Rgba64, Rgba64, Vector2; color8: Color, Color, Single;
// float32: Vector4 x3). --spot-shadow N (256..4096, 2048) / --point-shadow N (64..1024, 256): shadow
// map sizes. --no-ssao: no SSAO at all; --ssao-half: SSAO and its blur at half size. --explain:
// print the effects, render targets (bytes) and passes built and left out, with each effect's
// compile time, against the all-features scene (built once more by the same code).
// --targets: every debug-sheet tile also at full size in DIR/targets/. --lights: keep only some of
// the seed's lights (d, s, p). --sync-passes (default on OSMesa): finish the device around each timed
// pass, so that a deferring CPU rasterizer's work is counted in the right pass.
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

#include "common/program_registry.h"
#include "common/run_options.h"
#include "deferred/run_deferred.h"

namespace {

int usage(const char* message) {
    if (message) std::fprintf(stderr, "fxdemo: %s\n", message);
    std::fprintf(stderr,
                 "usage: fxdemo deferred [--size WxH] [--frames N] [--out DIR] [--gpu] [--window]\n"
                 "                       [--camera PX,PY,PZ,TX,TY,TZ] [--ssao RADIUS,SCALE] [--lights dsp]\n"
                 "                       [--no-debug-views] [--targets] [--[no-]sync-passes] [--content DIR] [--hlsl DIR]\n"
                 "                       [--gbuffer tutorial|color8|float32] [--spot-shadow N] [--point-shadow N]\n"
                 "                       [--no-ssao] [--ssao-half] [--explain]\n");
    for (const auto& [name, program] : fxdemo::programs()) std::fprintf(stderr, "       %s\n", program.usage.c_str());
    std::fprintf(stderr, "the four demos also take --check-finite: after each pass, stop at the first NaN/Inf in a target;\n"
                         "and --define NAME=VALUE (repeatable): a #define every effect is compiled with,\n"
                         "e.g. --define 'pow(x, y)=pow(max(x, 1e-30), y)' (see fxdemo stability)\n");
    return 2;
}

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

int main(int argc, char** argv) {
    if (argc < 2) return usage(nullptr);
    const std::string program = argv[1];
    if (program != "deferred") {
        auto found = fxdemo::programs().find(program);
        if (found != fxdemo::programs().end()) {
            try {
                return found->second.main(argc - 1, argv + 1);
            } catch (const std::exception& e) {  // e.g. --check-finite's NonFiniteError
                std::fprintf(stderr, "fxdemo %s: %s\n", program.c_str(), e.what());
                return 1;
            }
        }
        std::string known = "deferred";
        for (const auto& [name, registered] : fxdemo::programs()) known += ", " + name;
        return usage(("unknown program '" + program + "' (known: " + known + ")").c_str());
    }

    TheCansinDeferredRenderer::RunOptions options;
    // The options every program shares (--size, --frames, --out, --gpu, --window, --check-finite,
    // --define) are parsed by common/run_options, as the other programs do.
    fxport::demo::CommonOptions common;
    common.width = options.width;
    common.height = options.height;
    common.outDir = options.outDir;
    for (int i = 2; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
        std::string error;
        const fxport::demo::OptionResult parsed = fxport::demo::parseCommonOption(argc, argv, i, common, error);
        if (parsed == fxport::demo::OptionResult::Error) return usage(error.c_str());
        if (parsed == fxport::demo::OptionResult::Consumed) continue;
        if (arg == "--camera") {
            const char* v = value();
            std::vector<float> f;
            if (!v || !parseFloats(v, f, 6)) return usage("--camera wants PX,PY,PZ,TX,TY,TZ");
            options.cameraPosition = fxport::Vector3(f[0], f[1], f[2]);
            options.cameraTarget = fxport::Vector3(f[3], f[4], f[5]);
        } else if (arg == "--ssao") {
            const char* v = value();
            std::vector<float> f;
            if (!v || !parseFloats(v, f, 2)) return usage("--ssao wants RADIUS,SCALE");
            options.sampleRadius = f[0];
            options.distanceScale = f[1];
        } else if (arg == "--lights") {
            const char* v = value();
            if (!v || std::string(v).find_first_not_of("dsp") != std::string::npos)
                return usage("--lights wants letters of d (directional), s (spot), p (point)");
            options.lights = v;
        } else if (arg == "--no-debug-views") {
            options.debugViews = false;
        } else if (arg == "--sync-passes") {
            options.syncPasses = true;
        } else if (arg == "--no-sync-passes") {
            options.syncPasses = false;
        } else if (arg == "--gbuffer") {
            using Formats = TheCansinDeferredRenderer::Game1::DemoSettings::GBufferFormats;
            const std::string v = i + 1 < argc ? argv[++i] : "";
            if (v == "tutorial") options.gbufferFormats = Formats::Tutorial;
            else if (v == "color8") options.gbufferFormats = Formats::Color8;
            else if (v == "float32") options.gbufferFormats = Formats::Float32;
            else return usage(("--gbuffer wants tutorial, color8 or float32, not '" + v + "'").c_str());
        } else if (arg == "--spot-shadow" || arg == "--point-shadow") {
            const char* v = value();
            const bool spot = arg == "--spot-shadow";
            const int lo = spot ? 256 : 64, hi = spot ? 4096 : 1024;
            char* end = nullptr;
            const long n = v ? std::strtol(v, &end, 10) : 0;
            if (!v || *end || n < lo || n > hi)
                return usage((arg + " wants a size in " + std::to_string(lo) + ".." + std::to_string(hi) + ", not '" +
                              (v ? v : "") + "'").c_str());
            (spot ? options.spotShadowMapSize : options.pointShadowMapSize) = int(n);
        } else if (arg == "--no-ssao") {
            options.ssao = false;
        } else if (arg == "--ssao-half") {
            options.ssaoHalfResolution = true;
        } else if (arg == "--explain") {
            options.explain = true;
        } else if (arg == "--targets") {
            options.fullSizeImages = true;
        } else if (arg == "--content") {
            const char* v = value();
            if (!v) return usage("--content wants a folder");
            options.contentDir = v;
        } else if (arg == "--hlsl") {
            const char* v = value();
            if (!v) return usage("--hlsl wants a folder");
            options.hlslDir = v;
        } else {
            return usage(("unknown option '" + arg + "'").c_str());
        }
    }

    options.width = common.width;
    options.height = common.height;
    options.frames = common.frames;
    options.outDir = common.outDir;
    options.outDirGiven = common.outDirGiven;
    options.platform = common.platform;
    options.checkFinite = common.checkFinite;
    options.defines = common.defines;

    try {
        return TheCansinDeferredRenderer::RunDeferred(options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fxdemo: %s\n", e.what());
        return 1;
    }
}
