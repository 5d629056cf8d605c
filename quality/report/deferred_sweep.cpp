// The XNA 4 deferred renderer (seed 000): G-buffer formats, spot and point shadow-map sizes, SSAO
// on/off and at half resolution, render size. Two errors per setting, a smaller render size scaled
// up bilinearly before each comparison:
//  * the final image against the highest setting in float32 (Float32 G-buffer, 4096 spot / 1024
//    point shadow maps, SSAO at full resolution) at the report's size (SSAO has no exact answer);
//  * the LightMap target against the exact light map of that highest setting's frame
//    (report/deferred_light_map_reference.h: unshadowed lighting in double on its float32 G-buffer,
//    shadows by ray casting the scene's triangles).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <memory>

#include "deferred/game1.h"
#include "deferred/run_deferred.h"
#include "report/deferred_light_map_reference.h"
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

// Bilinear (pixel centres aligned) from w x h to W x H, `n` channels per pixel.
std::vector<double> upscale(const std::vector<double>& rgb, int w, int h, int W, int H, int n = 3) {
    if (w == W && h == H) return rgb;
    const std::size_t N = std::size_t(n);
    std::vector<double> out(std::size_t(W) * std::size_t(H) * N);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const double sx = std::clamp((x + 0.5) * w / W - 0.5, 0.0, double(w - 1));
            const double sy = std::clamp((y + 0.5) * h / H - 0.5, 0.0, double(h - 1));
            const int x0 = int(sx), y0 = int(sy), x1 = std::min(x0 + 1, w - 1), y1 = std::min(y0 + 1, h - 1);
            const double fx = sx - x0, fy = sy - y0;
            for (int k = 0; k < n; ++k) {
                auto at = [&](int xi, int yi) { return rgb[(std::size_t(yi) * std::size_t(w) + std::size_t(xi)) * N + std::size_t(k)]; };
                out[(std::size_t(y) * std::size_t(W) + std::size_t(x)) * N + std::size_t(k)] =
                    (at(x0, y0) * (1 - fx) + at(x1, y0) * fx) * (1 - fy) + (at(x0, y1) * (1 - fx) + at(x1, y1) * fx) * fy;
            }
        }
    return out;
}

// Where a light map differs from the exact one: |difference| x 4, the largest of R, G, B, A
// (specular), as grey RGB; pixels without an exact answer in dark red.
std::vector<double> difference(const std::vector<double>& lightMap, const ExactLightMap& exact,
                               const std::vector<double>* against = nullptr) {
    const std::vector<double>& reference = against ? *against : exact.rgba;
    std::vector<double> out;
    for (std::size_t p = 0; p < exact.defined.size(); ++p) {
        double d = 0;
        for (std::size_t c = 0; c < 4; ++c) d = std::max(d, std::fabs(lightMap[p * 4 + c] - reference[p * 4 + c]));
        if (exact.defined[p]) out.insert(out.end(), {4 * d, 4 * d, 4 * d});
        else out.insert(out.end(), {0.5, 0.0, 0.0});
    }
    return out;
}

struct Images {
    std::vector<double> image;     // final image, RGB, W x H
    std::vector<double> lightMap;  // LightMap target, RGBA, W x H
    ExactLightMap exactLightMap;   // when asked for (needs the Float32 G-buffer)
};

// Runs the game with `k`; fills the times of `m` when given; returns its images at W x H.
// `exactLightMap`: when given, the setting's light-map difference from it is saved beside its image.
Images run(const SweepOptions& options, int W, int H, const Knobs& k, Measurement* m, bool exact = false,
           const ExactLightMap* exactLightMap = nullptr) {
    Game1 game;
    const int w = std::max(8, int(std::lround(W * k.scale))), h = std::max(8, int(std::lround(H * k.scale)));
    game.graphics.PreferredBackBufferWidth = w;
    game.graphics.PreferredBackBufferHeight = h;
    game.graphics.platform = options.platform;
    // The viewpoint and SSAO values `fxdemo deferred` renders with (Game1's own defaults are the
    // seed's: a camera at floor height and SSAO radius 0, which would leave half the image black and
    // the SSAO knobs measuring nothing).
    const TheCansinDeferredRenderer::RunOptions shown;
    game.demo.cameraPosition = shown.cameraPosition;
    game.demo.cameraTarget = shown.cameraTarget;
    game.demo.sampleRadius = shown.sampleRadius;
    game.demo.distanceScale = shown.distanceScale;
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
    Images images;
    images.image = upscale(toRgb(game.GraphicsDevice->GetBackBufferData()), w, h, W, H);
    images.lightMap = upscale(readDeferredLightMap(game), w, h, W, H, 4);
    if (m && exactLightMap) {
        std::string name = m->knob + "_" + m->setting;
        for (char& c : name)
            if (!std::isalnum(static_cast<unsigned char>(c))) c = '-';
        saveReference(*game.GraphicsDevice, options, "deferred", difference(images.lightMap, *exactLightMap), W, H,
                      "light-map-difference-x4_" + name + ".png");
    }
    if (exact) {
        images.exactLightMap = exactDeferredLightMap(game);
        // Both light maps of this frame, the GPU's and the exact one, beside the settings' images
        // (RGB; their A, the specular sum, is not shown).
        auto rgbOf = [](const std::vector<double>& rgba) {
            std::vector<double> rgb;
            for (std::size_t i = 0; i < rgba.size(); i += 4) rgb.insert(rgb.end(), {rgba[i], rgba[i + 1], rgba[i + 2]});
            return rgb;
        };
        saveReference(*game.GraphicsDevice, options, "deferred", rgbOf(images.exactLightMap.rgba), w, h, "light-map_exact.png");
        saveReference(*game.GraphicsDevice, options, "deferred", rgbOf(images.lightMap), w, h, "light-map_highest-setting.png");
        saveReference(*game.GraphicsDevice, options, "deferred", difference(images.lightMap, images.exactLightMap), w, h,
                      "light-map_highest-setting_difference-x4.png");
        saveReference(*game.GraphicsDevice, options, "deferred", rgbOf(images.exactLightMap.idealEsmRgba), w, h, "light-map_ideal-esm.png");
        saveReference(*game.GraphicsDevice, options, "deferred",
                      difference(images.lightMap, images.exactLightMap, &images.exactLightMap.idealEsmRgba), w, h,
                      "light-map_highest-setting_vs-ideal-esm_difference-x4.png");
        saveReference(*game.GraphicsDevice, options, "deferred",
                      difference(images.exactLightMap.idealEsmRgba, images.exactLightMap), w, h,
                      "light-map_ideal-esm_vs-exact_difference-x4.png");
        // Which pixels the "off terminator" error leaves out: terminator white, silhouettes grey.
        std::vector<double> mask;
        for (std::size_t i = 0; i < images.exactLightMap.defined.size(); ++i) {
            const double v = images.exactLightMap.terminator[i] ? 1.0 : images.exactLightMap.defined[i] ? 0.0 : 0.5;
            mask.insert(mask.end(), {v, v, v});
        }
        saveReference(*game.GraphicsDevice, options, "deferred", mask, w, h, "light-map_left-out_terminator-white_silhouette-grey.png");
    }
    game.getDeferredRenderer().setGpuTimer(nullptr);
    if (game.hasSSAO()) game.getSSAO().setGpuTimer(nullptr);
    game.demo.gpuTimer = nullptr;
    return images;
}

}  // namespace

std::vector<Measurement> sweepDeferred(const SweepOptions& options) {
    const int W = options.width ? options.width : 800, H = options.height ? options.height : 600;
    using F = Settings::GBufferFormats;
    Knobs best;
    best.formats = F::Float32, best.spot = 4096, best.point = 1024;
    const Images reference = run(options, W, H, best, nullptr, true);
    const auto undefined = std::count(reference.exactLightMap.defined.begin(), reference.exactLightMap.defined.end(), 0);
    std::vector<char> offTerminator = reference.exactLightMap.defined;
    for (std::size_t i = 0; i < offTerminator.size(); ++i) offTerminator[i] &= char(!reference.exactLightMap.terminator[i]);
    const auto terminator = std::count(offTerminator.begin(), offTerminator.end(), 0) - undefined;
    // How far the exponential shadow test itself is from hard shadows, with a perfect shadow map.
    const ImageError esmItself = compareImages(reference.exactLightMap.idealEsmRgba, reference.exactLightMap.rgba,
                                               "deferred ideal-ESM light map", &reference.exactLightMap.defined);
    char leftOut[640];
    std::snprintf(leftOut, sizeof leftOut,
                  "; silhouette pixels, where the passes shade no surface, left out: %.1f %%. \"off term.\": also "
                  "without the %.1f %% of pixels on a shadowed light's terminator (lit by the smooth G-buffer normal "
                  "while the mesh facet faces away: the ray cast shadows them, a shadow map of any size lights them). "
                  "\"vs ESM\": against the light map the effects' exponential shadow test gives with exact, infinitely fine "
                  "shadow maps (occluder distances by ray casting), i.e. the shadow maps' sampling error alone; that "
                  "ideal-ESM light map is itself RMS %.5f (max %.4f) from the exact one",
                  100.0 * double(undefined) / double(offTerminator.size()), 100.0 * double(terminator) / double(offTerminator.size()),
                  esmItself.rms, esmItself.max);
    const std::string lightMapReference =
        std::string("exact light map (lighting in double, shadows by ray casting the scene's triangles) on the highest "
                    "setting's float32 G-buffer") + leftOut;

    struct Setting {
        std::string knob, setting;
        Knobs k;
        bool seed;
    };
    const Knobs seed;
    std::vector<Setting> settings;
    auto with = [&](auto change) { Knobs k = seed; change(k); return k; };
    settings.push_back({"G-buffer formats", "Rgba64/Rgba64/Vector2 (tutorial)", seed, true});
    settings.push_back({"G-buffer formats", "Color/Color/Single (SSAO white: it reads depth from .g)", with([](Knobs& k) { k.formats = F::Color8; }), false});
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
        m.lightMapReference = lightMapReference;
        const Images images = run(options, W, H, s.k, &m, false, &reference.exactLightMap);
        m.error = compareImages(images.image, reference.image, "deferred " + s.knob + " " + s.setting);
        m.lightMapError = compareImages(images.lightMap, reference.exactLightMap.rgba, "deferred light map " + s.knob + " " + s.setting,
                                        &reference.exactLightMap.defined);
        m.lightMapErrorOffTerminator = compareImages(images.lightMap, reference.exactLightMap.rgba,
                                                     "deferred light map off terminator " + s.knob + " " + s.setting, &offTerminator);
        m.lightMapErrorVsIdealEsm = compareImages(images.lightMap, reference.exactLightMap.idealEsmRgba,
                                                  "deferred light map vs ideal ESM " + s.knob + " " + s.setting,
                                                  &reference.exactLightMap.defined);
        m.hasLightMapError = true;
        out.push_back(m);
        if (options.progress) options.progress(m);
    }
    return out;
}

}  // namespace fxport::report
