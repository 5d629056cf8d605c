// `fxdemo report`: for each demo, sweeps the knobs that trade quality for time and measures both
// (issue 6, part 1). Each setting builds the demo's game in-process, runs N frames with the GPU
// timer, reads back the final image and compares it with a reference image of the same scene (see
// each *_sweep.cpp for which). Writes DIR/report.md, DIR/report.csv, DIR/report.png and each
// setting's image under DIR/images/.
//
//   fxdemo report [--out DIR] [--gpu] [--frames N] [--size WxH] [--quick] [--check] [--demos a,b,...] [--bounds]
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <string>

#include "common/program_registry.h"
#include "common/run_options.h"
#include "report/report_files.h"
#include "report/report_plot.h"
#include "report/sweep.h"

namespace fxport::report {

namespace {

int usage(const std::string& message) { return demo::usageError("report", message); }

const Measurement* find(const std::vector<Measurement>& rows, const std::string& demo, const std::string& knob,
                        const std::string& setting) {
    for (const Measurement& m : rows)
        if (m.demo == demo && m.knob == knob && m.setting == setting) return &m;
    return nullptr;
}

// --check: properties that must hold whatever the machine (ctest). Prints each; false if any fails.
bool checkReport(const std::vector<Measurement>& rows, const std::string& plot) {
    bool ok = true;
    auto expect = [&](bool condition, const std::string& what) {
        std::printf("check %s: %s\n", what.c_str(), condition ? "ok" : "FAIL");
        ok = ok && condition;
    };
    for (const Measurement& m : rows)
        expect(m.frameMs > 0 && std::isfinite(m.frameMs) && std::isfinite(m.error.rms) && m.error.max >= m.error.rms,
               m.demo + " " + m.knob + " " + m.setting + ": time > 0, finite RMS, max >= RMS");
    // The seed's float32 G-buffer against the exact CPU image: only the back buffer's 8-bit rounding
    // and edge pixels remain; 8-bit unorm clamps the signed normals, so it must be far worse.
    const Measurement* f32 = find(rows, "rastertek50", "target format", "R32G32B32A32_FLOAT");
    const Measurement* u8 = find(rows, "rastertek50", "target format", "R8G8B8A8_UNORM");
    if (f32 && u8) {
        expect(f32->error.rms < 2.0 / 255, "rastertek50 R32G32B32A32_FLOAT RMS < 2/255 against the CPU reference");
        expect(u8->error.rms > 4 * f32->error.rms, "rastertek50 8-bit unorm error > 4x the float32 error");
    }
    // More rays can only resolve the casters' outlines better.
    const Measurement *fewest = nullptr, *most = nullptr;
    for (const Measurement& m : rows)
        if (m.demo == "lighting2d" && m.knob == "ray count" && std::isdigit(static_cast<unsigned char>(m.setting.back()))) {
            if (!fewest) fewest = &m;
            most = &m;
        }
    if (fewest && most && fewest != most)
        expect(most->error.rms < fewest->error.rms, "lighting2d: " + most->setting + " rays more exact than " + fewest->setting);
    // A float light map and G-buffer against the chapter's 8-bit ones: no clamp, no 8-bit normals.
    const Measurement* tutorial = find(rows, "pointlights", "G-buffer formats", "Color/Color/Single, light Color");
    const Measurement* float32 = find(rows, "pointlights", "G-buffer formats", "Vector4 x2/Single, light Vector4");
    if (tutorial && float32) expect(float32->error.rms < tutorial->error.rms, "pointlights: float32 formats more exact than the chapter's");
    // The deferred light map against the exact one (ray-cast shadows): finite. A larger point shadow
    // cube is asserted nearer the highest setting's final image than the smallest; against the exact
    // light map that order shows at 800x600 (docs/report) but not at the test's 96x64 (cube 64: LM
    // RMS 0.043, 256: 0.053 there, on llvmpipe), which is not explained yet.
    const Measurement *smallestCube = nullptr, *largestCube = nullptr;
    for (const Measurement& m : rows) {
        if (!m.hasLightMapError) continue;
        expect(std::isfinite(m.lightMapError.rms) && m.lightMapError.max >= m.lightMapError.rms && m.lightMapError.max <= 1,
               m.demo + " " + m.knob + " " + m.setting + ": light map error finite, RMS <= max <= 1");
        // The effects' exponential test with perfect shadow maps is nearer what the GPU drew than
        // hard shadows are: the test itself, not the maps, is most of the light map's error.
        if (m.seedDefault)
            expect(m.lightMapErrorVsIdealEsm.rms < m.lightMapError.rms,
                   m.demo + " " + m.knob + " " + m.setting + ": light map nearer the ideal-ESM light map than the exact one");
        if (m.knob == "point shadow cube") {
            if (!smallestCube) smallestCube = &m;
            largestCube = &m;
        }
    }
    if (smallestCube && largestCube && smallestCube != largestCube)
        expect(largestCube->error.rms < smallestCube->error.rms,
               "deferred: point shadow cube " + largestCube->setting + " nearer the highest setting than " + smallestCube->setting);
    expect(std::filesystem::file_size(plot) > 1000, "report.png written");
    return ok;
}

int runReport(int argc, char** argv) {
    demo::CommonOptions common;
    common.outDir = "fxdemo-out/report";
    bool quick = false;
    bool check = false;
    std::string demos = "rastertek50,lighting2d,pointlights,deferred";
    std::string command = "fxdemo report";
    for (int i = 1; i < argc; ++i) command += std::string(" ") + argv[i];
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        std::string error;
        const int at = i;
        switch (demo::parseCommonOption(argc, argv, i, common, error)) {
        case demo::OptionResult::Consumed:
            if (arg == "--window") return usage("--window: the report runs headless (OSMesa, or EGL with --gpu); leave it out");
            continue;
        case demo::OptionResult::Error: return usage(error);
        case demo::OptionResult::NotMine: break;
        }
        i = at;
        if (arg == "--quick") quick = true;
        else if (arg == "--check") check = true;
        else if (arg == "--demos") {
            if (i + 1 >= argc) return usage(demo::wants("--demos", "a list of rastertek50, lighting2d, pointlights, deferred", nullptr));
            demos = argv[++i];
        } else return usage(demo::unknownOption("report", arg));
    }
    if (std::string error; !demo::checkCommonOptions(common, error)) return usage(error);
    if (!common.defines.empty()) return usage("--define: the report measures the effects as written");
    if (common.checkFinite) return usage("--check-finite: run it on a demo (fxdemo <name> --check-finite)");
    SweepOptions options;
    options.platform = common.platform;
    options.quick = quick;
    options.frames = common.frames.value_or(quick ? 1 : (common.platform == "osmesa" ? 3 : 30));
    options.warmupFrames = common.platform == "osmesa" ? 1 : 10;
    options.warmupSeconds = common.platform == "osmesa" ? 0 : 1.0;
    bool sizeGiven = false;
    for (int i = 1; i < argc; ++i) sizeGiven |= std::string(argv[i]) == "--size";
    if (sizeGiven) options.width = common.width, options.height = common.height;
    else if (quick) options.width = 96, options.height = 64;
    options.outDir = common.outDir;
    options.bounds = common.bounds;
    options.progress = [](const Measurement& m) {
        std::printf("  %-12s %-20s %-40s %9.3f ms  RMS %.5f  max %.4f  PSNR %6.2f dB", m.demo.c_str(), m.knob.c_str(),
                    m.setting.c_str(), m.frameMs, m.error.rms, m.error.max, m.error.psnr);
        if (m.hasLightMapError)
            std::printf("  light map: RMS %.5f  max %.4f  PSNR %6.2f dB (off terminator: RMS %.5f; vs ideal ESM: RMS %.5f  max %.4f)",
                        m.lightMapError.rms, m.lightMapError.max, m.lightMapError.psnr, m.lightMapErrorOffTerminator.rms,
                        m.lightMapErrorVsIdealEsm.rms, m.lightMapErrorVsIdealEsm.max);
        for (std::size_t i = 0; i < m.passBoundMs.size() && i < m.passMs.size(); ++i)  // --bounds
            if (m.passBoundMs[i] > 0)
                std::printf("%s%s %.3f (fill %.3f fetch %.3f bound %.3f x%.1f)", i ? ", " : "\n    passes: ",
                            m.passMs[i].first.c_str(), m.passMs[i].second, i < m.passFillMs.size() ? m.passFillMs[i] : 0.0,
                            i < m.passFetchMs.size() ? m.passFetchMs[i] : 0.0, m.passBoundMs[i],
                            m.passMs[i].second / m.passBoundMs[i]);
        std::printf("\n");
        std::fflush(stdout);
    };
    std::filesystem::create_directories(options.outDir);

    std::vector<Measurement> rows;
    auto wanted = [&](const std::string& name) { return ("," + demos + ",").find("," + name + ",") != std::string::npos; };
    for (const std::string& name : {std::string("rastertek50"), std::string("lighting2d"), std::string("pointlights"),
                                    std::string("deferred"), std::string("-")})
        if (name != "-" && !wanted(name) && demos.find(name) != std::string::npos) return usage(demo::wants("--demos", "a comma-separated list of rastertek50, lighting2d, pointlights, deferred", demos.c_str()));
    using Sweep = std::vector<Measurement> (*)(const SweepOptions&);
    const std::pair<const char*, Sweep> sweeps[] = {{"rastertek50", sweepRastertek50}, {"lighting2d", sweepLighting2d},
                                                    {"pointlights", sweepPointLights}, {"deferred", sweepDeferred}};
    int matched = 0;
    for (const auto& [name, sweep] : sweeps) {
        if (!wanted(name)) continue;
        ++matched;
        std::printf("%s:\n", name);
        for (Measurement& m : sweep(options)) rows.push_back(m);
    }
    if (matched == 0) return usage(demo::wants("--demos", "a comma-separated list of rastertek50, lighting2d, pointlights, deferred", demos.c_str()));

    // A device for the plot's text (and the renderer's name).
    PresentationParameters parameters;
    parameters.platform = options.platform;
    parameters.BackBufferWidth = 64, parameters.BackBufferHeight = 64;
    GraphicsDevice device(parameters);
    RunInfo info;
    info.command = command;
    info.renderer = device.rendererName();
    info.frames = options.frames;
    info.warmupFrames = options.warmupFrames;
    info.warmupSeconds = options.warmupSeconds;
    const std::time_t now = std::time(nullptr);
    char date[32];
    std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
    info.date = date;
    const auto dir = std::filesystem::path(options.outDir);
    writeCsv(rows, (dir / "report.csv").string());
    writeMarkdown(rows, info, (dir / "report.md").string());
    writePlot(device, rows, "fxdemo report: RMS error vs median GPU frame time -- " + info.renderer + ", " + date,
              (dir / "report.png").string());
    std::printf("wrote %s/report.md, report.csv, report.png\n", options.outDir.c_str());
    return check && !checkReport(rows, (dir / "report.png").string()) ? 1 : 0;
}

}  // namespace

}  // namespace fxport::report

FXDEMO_PROGRAM(report,
               "fxdemo report [--out DIR] [--gpu] [--frames N] [--size WxH] [--quick] [--check] [--demos a,b,...] [--bounds]\n"
               "  Error against GPU time for each demo's quality knobs: DIR/report.md, report.csv, report.png.\n"
               "  --out DIR      where the report goes (fxdemo-out/report)\n"
               "  --gpu          headless on the GPU (EGL) instead of OSMesa\n"
               "  --frames N     timed frames per setting (OSMesa 3, GPU 30; --quick 1)\n"
               "  --size WxH     the demos' size (each demo's own; --quick 96x64)\n"
               "  --quick        tiny sizes, one timed frame: a smoke run\n"
               "  --check        assert what must hold on any machine (exit 1 if not)\n"
               "  --demos LIST   which sweeps: rastertek50,lighting2d,pointlights,deferred (all)\n"
               "  --bounds       each pass's bound (fill, texture fetches) and ms / bound beside its time (common/pass_bound.h)",
               fxport::report::runReport);
