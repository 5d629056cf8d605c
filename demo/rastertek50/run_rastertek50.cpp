// `fxdemo rastertek50`: Rastertek DirectX 10 tutorial 50, "Deferred Shading" (seed 004), on fxport.
// The seed's SystemClass (window, message loop) is this function: it creates the ApplicationClass
// and calls Frame() once per frame.
//
//   fxdemo rastertek50 [--size WxH] [--frames N] [--out DIR] [--gpu] [--hlsl DIR] [--check]
//                      [--explain]
//
// Headless (OSMesa; --gpu: EGL) it renders N frames (default 25: the cube turns pi/100 per frame,
// so frame 25 shows it at 45 degrees; the rotation depends only on the frame number), prints the
// median GPU time of each pass, and writes DIR/final.png (the back buffer) and DIR/debug.png (the
// two G-buffer targets side by side: left the colour target, right the normal target shown as
// n * 0.5 + 0.5, with the cleared background, normal (0,0,0), left black). The port draws through
// fxport's D3D10 front end, whose swap chain is headless: --window is refused (D3DClass). --check:
// the last frame against a CPU reference (reference_check.h); exit code 1 when it is off. --explain:
// the effects (load and compile time), render targets (bytes) and passes built; the seed's
// pipeline has no optional part, so this run is its all-features configuration and nothing is left
// out.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/build_report.h"
#include "common/frame_loop.h"
#include "common/pass_timer.h"
#include "common/program_registry.h"
#include "common/run_options.h"
#include "fxport/d3d11/core_access.h"
#include "fxport/graphics.h"
#include "fxport/platform/graphics_context.h"
#include "rastertek50/applicationclass.h"
#include "rastertek50/reference_check.h"

namespace Rastertek50 {

namespace {

int usage(const std::string& message) { return fxport::demo::usageError("rastertek50", message); }

std::uint8_t toByte(float v) {
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    return std::uint8_t(std::lround(v * 255.0f));
}

// The PNG of `texels` (w x h, top row first), encoded by a Texture2D of the device core.
void SavePng(ApplicationClass& application, const std::vector<fxport::Color>& texels, int w, int h, const std::string& path) {
    fxport::Texture2D image(application.GetD3D()->GetCoreDevice(), w, h, false, fxport::SurfaceFormat::Color);
    image.SetData(texels);
    image.SaveAsPng(path);
}

// The two G-buffer targets side by side (see the top of this file), read back from the D3D10
// textures; the PNG is encoded by a Texture2D of the device core.
void WriteDebugImage(ApplicationClass& application, const std::string& path) {
    DeferredBuffersClass& buffers = *application.GetDeferredBuffers();
    ID3D10Device* device = application.GetD3D()->GetDevice();
    const int w = buffers.GetTextureWidth(), h = buffers.GetTextureHeight();
    const std::vector<fxport::Vector4> colors = buffers.GetTargetData(device, 0);
    const std::vector<fxport::Vector4> normals = buffers.GetTargetData(device, 1);
    if (colors.size() != std::size_t(w) * std::size_t(h) || normals.size() != colors.size())
        throw std::runtime_error("the G-buffer targets could not be read back");
    std::vector<fxport::Color> sheet(std::size_t(2 * w) * std::size_t(h));
    for (int y = 0; y < h; ++y) {
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            const fxport::Vector4 c = colors[i];
            const fxport::Vector4 n = normals[i];
            fxport::Color& left = sheet[std::size_t(y) * std::size_t(2 * w) + std::size_t(x)];
            fxport::Color& right = sheet[std::size_t(y) * std::size_t(2 * w) + std::size_t(w + x)];
            left = fxport::Color(toByte(c.X), toByte(c.Y), toByte(c.Z), std::uint8_t(255));
            const bool empty = std::fabs(n.X) + std::fabs(n.Y) + std::fabs(n.Z) < 1e-4f;
            right = empty ? fxport::Color(std::uint8_t(0), std::uint8_t(0), std::uint8_t(0), std::uint8_t(255))
                          : fxport::Color(toByte(n.X * 0.5f + 0.5f), toByte(n.Y * 0.5f + 0.5f),
                                          toByte(n.Z * 0.5f + 0.5f), std::uint8_t(255));
        }
    }
    SavePng(application, sheet, 2 * w, h, path);
}

// The XNA name of a G-buffer format, as --explain prints target formats.
fxport::SurfaceFormat SurfaceFormatOf(DXGI_FORMAT format) {
    switch (format) {
    case DXGI_FORMAT_R32G32B32A32_FLOAT: return fxport::SurfaceFormat::Vector4;
    case DXGI_FORMAT_R16G16B16A16_FLOAT: return fxport::SurfaceFormat::HalfVector4;
    default: return fxport::SurfaceFormat::Color;
    }
}

// --explain: the two effects the shader classes created (the fxport::Effect under each
// ID3D10Effect), the G-buffer's two targets (the first listed with the depth buffer bound with the
// set) and the passes the timer saw.
fxport::demo::BuildReport ReportBuild(ApplicationClass& application, const fxport::GpuTimer& timer) {
    fxport::demo::BuildReport report;
    report.addEffect("rastertek/deferred.fx", fxport::d3d11::CoreEffectOf(*application.GetDeferredShader()->GetEffect()->GetD3DX11Effect()));
    report.addEffect("rastertek/light.fx", fxport::d3d11::CoreEffectOf(*application.GetLightShader()->GetEffect()->GetD3DX11Effect()));
    const DeferredBuffersClass& buffers = *application.GetDeferredBuffers();
    static const char* const names[BUFFER_COUNT] = {"colorTexture", "normalTexture"};  // light.fx's names
    for (int i = 0; i < BUFFER_COUNT; ++i) {
        fxport::demo::BuildReport::TargetEntry e;
        e.name = names[i];
        e.width = buffers.GetTextureWidth();
        e.height = buffers.GetTextureHeight();
        e.format = SurfaceFormatOf(buffers.GetFormat());
        e.depth = i == 0 ? fxport::DepthFormat::Depth24Stencil8 : fxport::DepthFormat::None;
        e.bytes = fxport::demo::RenderTargetBytes(e.width, e.height, 1, e.format, e.depth);
        report.targets.push_back(e);
    }
    report.addPasses(timer);
    report.addClears(application.GetD3D()->GetCoreDevice());
    return report;
}

int runRastertek50(int argc, char** argv) {
    fxport::demo::CommonOptions common;
    common.outDir = "fxdemo-out/rastertek50";
    std::string hlslDir = FXPORT_HLSL_DIR;
    bool check = false;
    bool explain = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
        std::string error;
        fxport::demo::OptionResult parsed = fxport::demo::parseCommonOption(argc, argv, i, common, error);
        if (parsed == fxport::demo::OptionResult::Error) return usage(error);
        if (parsed == fxport::demo::OptionResult::Consumed) continue;
        if (arg == "--check") {
            check = true;
        } else if (arg == "--explain") {
            explain = true;
        } else if (arg == "--hlsl") {
            const char* v = value();
            if (!v) return usage(fxport::demo::wants("--hlsl", "a folder", v));
            hlslDir = v;
        } else {
            return usage(fxport::demo::unknownOption("rastertek50", arg));
        }
    }
    if (std::string error; !fxport::demo::checkCommonOptions(common, error)) return usage(error);

    try {
        ApplicationClass application;
        application.SetDefines(common.defines);
        if (!application.Initialize(common.platform, hlslDir, common.width, common.height)) return 1;
        fxport::GraphicsDevice& device = application.GetD3D()->GetCoreDevice();
        auto timer = std::make_unique<fxport::GpuTimer>(device);
        application.SetGpuTimer(timer.get());
        const bool sync = common.platform == "osmesa";
        fxport::demo::PassTimer::syncDevice = sync ? &device : nullptr;
        fxport::demo::PassBound::setUp(device, common.fillRateGBps, common.bounds);
        fxport::demo::FiniteCheckScope finite(&device, common.checkFinite);
        std::printf("fxdemo rastertek50: %dx%d on %s (%s)\n", common.width, common.height, common.platform.c_str(),
                    device.rendererName().c_str());

        const int frameCount = fxport::demo::runFrameLoop(device, *timer, common.platform == "glfw", common.frames, 25,
                                                          [&](int, bool) { return application.Frame(); });
        fxport::demo::PassTimer::syncDevice = nullptr;
        fxport::demo::PassBound::device = nullptr;

        std::printf("%d frames, cube rotation %.4f rad; median GPU time per pass%s:\n", frameCount,
                    double(application.GetRotation()), sync ? " (each pass finished before and after)" : "");
        for (const fxport::GpuTimer::Section& section : timer->Sections())
            std::printf("  %-12s %9.3f ms%s\n", section.name.c_str(), section.medianMs(),
                        fxport::demo::PassBound::columns(section).c_str());

        if (common.platform != "glfw" || common.outDirGiven) {
            std::filesystem::create_directories(common.outDir);
            const std::string finalPath = (std::filesystem::path(common.outDir) / "final.png").string();
            const std::string debugPath = (std::filesystem::path(common.outDir) / "debug.png").string();
            // What the window would show: DXGI presents the back buffer's RGB; its alpha is light.fx's
            // output (0 where the G-buffer is empty), so final.png is written opaque.
            std::vector<fxport::Color> shown = application.GetD3D()->GetBackBufferData();
            for (fxport::Color& c : shown) c.A = 255;
            SavePng(application, shown, common.width, common.height, finalPath);
            WriteDebugImage(application, debugPath);
            std::printf("wrote %s and %s\n", finalPath.c_str(), debugPath.c_str());
        }
        bool checked = true;
        if (check) checked = RunReferenceCheck(application);
        if (explain) {
            // The pipeline is fixed (no light types, shadows or options to leave out): the
            // all-features configuration is this build itself.
            const fxport::demo::BuildReport built = ReportBuild(application, *timer);
            fxport::demo::PrintExplain(stdout, built, built,
                                       "the seed's pipeline, which has no optional part (G-buffer pass, light pass): "
                                       "this run; nothing can be left out");
        }
        application.SetGpuTimer(nullptr);
        timer.reset();
        application.Shutdown();
        if (!checked) return 1;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "fxdemo rastertek50: %s\n", error.what());
        return 1;
    }
    return 0;
}

}  // namespace

}  // namespace Rastertek50

FXDEMO_PROGRAM(rastertek50,
               "fxdemo rastertek50 [--size WxH] [--frames N] [--out DIR] [--gpu] [--hlsl DIR] [--check]\n"
               "                          [--explain]\n"
               "  Rastertek DirectX 10 tutorial 50, deferred shading (seed 004), on fxport's D3D10 front end (headless:\n"
               "  no --window): writes DIR/final.png and DIR/debug.png.\n"
               "  --size WxH     back buffer size (800x600)      --frames N   frames to run headless\n"
               "  --out DIR      where the images go (fxdemo-out/rastertek50)\n"
               "  --hlsl DIR     the effects' folder (the source tree's hlsl/)\n"
               "  --check        compare the G-buffer and the frame with a CPU reference\n"
               "  --explain      print the effects, targets and passes built and left out",
               Rastertek50::runRastertek50);
