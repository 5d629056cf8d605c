#include "report/sweep.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "common/frame_loop.h"
#include "common/pass_bound.h"
#include "common/pass_timer.h"

namespace fxport::report {

void runTimedFrames(GraphicsDevice& device, GpuTimer& timer, const SweepOptions& options,
                    const std::function<void()>& frame, Measurement& m) {
    const bool sync = options.platform == "osmesa";
    demo::PassTimer::syncDevice = sync ? &device : nullptr;
    if (options.bounds) {
        // The limits are measured (or read from the cache) once per process: every setting shares them.
        if (!demo::PassBound::limits) demo::PassBound::limits = GpuLimits::ForDevice(device);
        demo::PassBound::device = &device;
        demo::PassBound::forgetRuns();
        demo::PassBound::tallyOn(device);
    }
    // Warm-up frames first (shader programs linked, targets first touched, GPU clocks up after the
    // CPU-only work of the previous setting): timed like the others, then dropped.
    int warmup = 0;
    const auto start = std::chrono::steady_clock::now();
    auto elapsed = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); };
    while (warmup < options.warmupFrames || elapsed() < options.warmupSeconds) {
        frame();
        timer.EndFrame();
        ++warmup;
        if (warmup % 8 == 0) device.finish();  // so that the clock measures the GPU's work
    }
    m.frames = demo::runFrameLoop(device, timer, false, options.frames, options.frames, [&](int, bool) {
        frame();
        return true;
    });
    demo::PassTimer::syncDevice = nullptr;
    demo::PassBound::device = nullptr;
    auto median = [&](std::vector<double> v) {
        if (v.size() > std::size_t(warmup)) v.erase(v.begin(), v.begin() + warmup);
        std::sort(v.begin(), v.end());
        return v.empty() ? 0.0 : (v.size() % 2 ? v[v.size() / 2] : 0.5 * (v[v.size() / 2 - 1] + v[v.size() / 2]));
    };
    m.passMs.clear();
    m.passBoundMs.clear();
    m.passFillMs.clear();
    m.passFetchMs.clear();
    for (const GpuTimer::Section& section : timer.Sections()) {
        if (section.name == "frame") {
            m.frameMs = median(section.milliseconds);
        } else {
            m.passMs.emplace_back(section.name, median(section.milliseconds));
            if (options.bounds) {
                const std::optional<demo::PassBound::Summary> bound = demo::PassBound::summary(section.name);
                m.passBoundMs.push_back(bound ? bound->estimate.boundMs() : 0.0);
                m.passFillMs.push_back(bound ? bound->estimate.fillMs : 0.0);
                m.passFetchMs.push_back(bound ? bound->estimate.fetchMs : 0.0);
            }
        }
    }
    m.size = std::to_string(device.PresentationParameters().BackBufferWidth) + "x" +
             std::to_string(device.PresentationParameters().BackBufferHeight);
}

namespace {

std::string slug(std::string s) {
    for (char& c : s)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '-';
    return s;
}

}  // namespace

void saveImage(GraphicsDevice& device, const SweepOptions& options, const Measurement& m) {
    if (options.outDir.empty()) return;
    const auto dir = std::filesystem::path(options.outDir) / "images" / m.demo;
    std::filesystem::create_directories(dir);
    device.SaveBackBufferAsPng((dir / (slug(m.knob) + "_" + slug(m.setting) + ".png")).string());
}

void saveImage(GraphicsDevice& device, const SweepOptions& options, const Measurement& m, const std::vector<Color>& pixels,
               int width, int height) {
    if (options.outDir.empty()) return;
    Texture2D image(device, width, height);
    image.SetData(pixels);
    const auto dir = std::filesystem::path(options.outDir) / "images" / m.demo;
    std::filesystem::create_directories(dir);
    image.SaveAsPng((dir / (slug(m.knob) + "_" + slug(m.setting) + ".png")).string());
}

void saveReference(GraphicsDevice& device, const SweepOptions& options, const std::string& demo,
                   const std::vector<double>& rgb, int width, int height, const std::string& name) {
    if (options.outDir.empty()) return;
    std::vector<Color> pixels(std::size_t(width) * std::size_t(height));
    for (std::size_t i = 0; i < pixels.size(); ++i) {
        auto byte = [&](int k) { return int(std::lround(std::clamp(rgb[i * 3 + std::size_t(k)], 0.0, 1.0) * 255)); };
        pixels[i] = Color(byte(0), byte(1), byte(2), 255);
    }
    Texture2D image(device, width, height);
    image.SetData(pixels);
    const auto dir = std::filesystem::path(options.outDir) / "images" / demo;
    std::filesystem::create_directories(dir);
    image.SaveAsPng((dir / name).string());
}

}  // namespace fxport::report
