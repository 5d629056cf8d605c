// The XNA 4 deferred renderer (seed 000): G-buffer formats, spot and point shadow-map sizes, SSAO
// on/off and at half resolution, render size. Reference: the highest setting in float32 (Float32
// G-buffer, 4096 spot / 1024 point shadow maps, SSAO at full resolution) at the report's size; a
// smaller render size is scaled up bilinearly before the comparison.
#include <algorithm>
#include <cmath>
#include <memory>

#include "deferred/game1.h"
#include "report/sweep.h"

namespace fxport::report {

namespace {

using TheCansinDeferredRenderer::Game1;
using Settings = Game1::DemoSettings;

struct Knobs {
    Settings::GBufferFormats formats = Settings::GBufferFormats::Tutorial;
    int spot = 2048, point = 256;
    bool ssao = true, half = false;
    double scale = 1.0;  // render size / report size
};

// Bilinear (pixel centres aligned) from w x h to W x H, RGB.
std::vector<double> upscale(const std::vector<double>& rgb, int w, int h, int W, int H) {
    if (w == W && h == H) return rgb;
    std::vector<double> out(std::size_t(W) * std::size_t(H) * 3);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const double sx = std::clamp((x + 0.5) * w / W - 0.5, 0.0, double(w - 1));
            const double sy = std::clamp((y + 0.5) * h / H - 0.5, 0.0, double(h - 1));
            const int x0 = int(sx), y0 = int(sy), x1 = std::min(x0 + 1, w - 1), y1 = std::min(y0 + 1, h - 1);
            const double fx = sx - x0, fy = sy - y0;
            for (int k = 0; k < 3; ++k) {
                auto at = [&](int xi, int yi) { return rgb[(std::size_t(yi) * std::size_t(w) + std::size_t(xi)) * 3 + std::size_t(k)]; };
                out[(std::size_t(y) * std::size_t(W) + std::size_t(x)) * 3 + std::size_t(k)] =
                    (at(x0, y0) * (1 - fx) + at(x1, y0) * fx) * (1 - fy) + (at(x0, y1) * (1 - fx) + at(x1, y1) * fx) * fy;
            }
        }
    return out;
}

// Runs the game with `k`; fills the times of `m` when `timed`; returns the final image at W x H.
std::vector<double> run(const SweepOptions& options, int W, int H, const Knobs& k, Measurement* m) {
    Game1 game;
    const int w = std::max(8, int(std::lround(W * k.scale))), h = std::max(8, int(std::lround(H * k.scale)));
    game.graphics.PreferredBackBufferWidth = w;
    game.graphics.PreferredBackBufferHeight = h;
    game.graphics.platform = options.platform;
    game.demo.debugViews = false;
    game.demo.gbufferFormats = k.formats;
    game.demo.spotShadowMapSize = k.spot;
    game.demo.pointShadowMapSize = k.point;
    game.demo.ssao = k.ssao;
    game.demo.ssaoHalfResolution = k.half;
    game.Start();
    auto timer = std::make_unique<GpuTimer>(*game.GraphicsDevice);
    game.getDeferredRenderer().setGpuTimer(timer.get());
    if (game.hasSSAO()) game.getSSAO().setGpuTimer(timer.get());
    game.demo.gpuTimer = timer.get();
    Measurement scratch;
    runTimedFrames(*game.GraphicsDevice, *timer, options, [&] { game.Tick(); }, m ? *m : scratch);
    if (m) saveImage(*game.GraphicsDevice, options, *m);
    std::vector<double> image = upscale(toRgb(game.GraphicsDevice->GetBackBufferData()), w, h, W, H);
    game.getDeferredRenderer().setGpuTimer(nullptr);
    if (game.hasSSAO()) game.getSSAO().setGpuTimer(nullptr);
    game.demo.gpuTimer = nullptr;
    return image;
}

}  // namespace

std::vector<Measurement> sweepDeferred(const SweepOptions& options) {
    const int W = options.width ? options.width : 800, H = options.height ? options.height : 600;
    using F = Settings::GBufferFormats;
    Knobs best;
    best.formats = F::Float32, best.spot = 4096, best.point = 1024;
    const std::vector<double> reference = run(options, W, H, best, nullptr);

    struct Setting {
        std::string knob, setting;
        Knobs k;
        bool seed;
    };
    const Knobs seed;
    std::vector<Setting> settings;
    auto with = [&](auto change) { Knobs k = seed; change(k); return k; };
    settings.push_back({"G-buffer formats", "Rgba64/Rgba64/Vector2 (tutorial)", seed, true});
    settings.push_back({"G-buffer formats", "Color/Color/Single", with([](Knobs& k) { k.formats = F::Color8; }), false});
    settings.push_back({"G-buffer formats", "Vector4 x3", with([](Knobs& k) { k.formats = F::Float32; }), false});
    for (int s : options.quick ? std::vector<int>{256, 2048} : std::vector<int>{256, 512, 1024, 2048, 4096})
        settings.push_back({"spot shadow map", std::to_string(s), with([&](Knobs& k) { k.spot = s; }), s == 2048});
    for (int s : options.quick ? std::vector<int>{64, 256} : std::vector<int>{64, 128, 256, 512, 1024})
        settings.push_back({"point shadow cube", std::to_string(s), with([&](Knobs& k) { k.point = s; }), s == 256});
    settings.push_back({"SSAO", "on (full resolution)", seed, true});
    settings.push_back({"SSAO", "half resolution", with([](Knobs& k) { k.half = true; }), false});
    settings.push_back({"SSAO", "off", with([](Knobs& k) { k.ssao = false; }), false});
    for (double s : options.quick ? std::vector<double>{1.0, 0.5} : std::vector<double>{1.0, 0.75, 0.5, 0.25}) {
        char name[48];
        std::snprintf(name, sizeof name, "%dx%d", int(std::lround(W * s)), int(std::lround(H * s)));
        settings.push_back({"render size", name, with([&](Knobs& k) { k.scale = s; }), s == 1.0});
    }

    std::vector<Measurement> out;
    for (const Setting& s : settings) {
        Measurement m;
        m.demo = "deferred";
        m.knob = s.knob;
        m.setting = s.setting;
        m.seedDefault = s.seed;
        m.reference = "highest setting in float32 (Vector4 x3, 4096/1024 shadows, full SSAO)";
        const std::vector<double> image = run(options, W, H, s.k, &m);
        m.error = compareImages(image, reference, "deferred " + s.knob + " " + s.setting);
        out.push_back(m);
        if (options.progress) options.progress(m);
    }
    return out;
}

}  // namespace fxport::report
