// GpuLimits: the fill, clear, fetch and compute-write rates the backend measures (gl/gl_limits_probe.cpp),
// cached per renderer string, and what the device's policies read from them.
#include "fxport/graphics/gpu_limits.h"

#include "fxport/graphics/graphics_device.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>

#include "device/device_probes.h"
#include "fxport/graphics/errors.h"

namespace fxport {

namespace {

const SurfaceFormat kFormats[] = {SurfaceFormat::Color,  SurfaceFormat::Rgba64, SurfaceFormat::HalfVector4,
                                  SurfaceFormat::Vector4, SurfaceFormat::Single, SurfaceFormat::Vector2};

std::string cacheFolder(const std::string& given) {
    if (!given.empty()) return given;
    if (const char* d = std::getenv("FXPORT_CACHE_DIR"); d && *d) return d;
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::string(x) + "/fxport";
    if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.cache/fxport";
    return ".fxport-cache";
}

}  // namespace

double GpuLimits::fillGBps(SurfaceFormat format, bool blended) const {
    auto rate = [&](const Fill& f) { return blended ? f.blendedGBps : f.opaqueGBps; };
    double slowest = 0;
    for (const Fill& f : fill) {
        if (f.format == format) return rate(f);
        slowest = slowest == 0 ? rate(f) : std::min(slowest, rate(f));
    }
    for (const Fill& f : fill)
        if (bytesPerPixel(f.format) == bytesPerPixel(format)) return rate(f);
    return slowest;
}

GpuLimits GpuLimits::Measure(GraphicsDevice& device, int size, int repeats) {
    GpuLimits limits =
        measureDeviceLimits(device, std::vector<SurfaceFormat>(std::begin(kFormats), std::end(kFormats)), size, repeats);
    limits.renderer = device.rendererName();
    return limits;
}

std::string GpuLimits::toText() const {
    std::ostringstream out;
    out.precision(6);
    out << "renderer " << renderer << "\n";
    for (const Fill& f : fill)
        out << "fill " << surfaceFormatName(f.format) << " " << f.opaqueGBps << " " << f.blendedGBps << "\n";
    out << "clear " << clearGBps << "\n";
    out << "fetch " << fetchGTexelsPerSecond << "\n";
    out << "compute " << computeWriteGBps << "\n";
    return out.str();
}

bool GpuLimits::fromText(const std::string& text, GpuLimits& out) {
    GpuLimits limits;
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        std::string key;
        fields >> key;
        if (key == "renderer") {
            limits.renderer = line.size() > 9 ? line.substr(9) : "";
        } else if (key == "fill") {
            std::string name;
            Fill f{};
            if (!(fields >> name >> f.opaqueGBps >> f.blendedGBps)) return false;
            bool known = false;
            for (SurfaceFormat format : kFormats)
                if (name == surfaceFormatName(format)) f.format = format, known = true;
            if (!known || !(f.opaqueGBps > 0 && f.blendedGBps > 0)) return false;
            limits.fill.push_back(f);
        } else if (key == "clear") {
            if (!(fields >> limits.clearGBps)) return false;
        } else if (key == "fetch") {
            if (!(fields >> limits.fetchGTexelsPerSecond)) return false;
        } else if (key == "compute") {
            if (!(fields >> limits.computeWriteGBps)) return false;
        } else if (!key.empty()) {
            return false;
        }
    }
    // A cache written before the compute rate was measured has none: measured again.
    if (limits.fill.size() != std::size(kFormats) || !(limits.clearGBps > 0) || !(limits.fetchGTexelsPerSecond > 0) ||
        !(limits.computeWriteGBps > 0))
        return false;
    out = limits;
    return true;
}

bool GpuLimits::softwareRenderer(const std::string& renderer) {
    for (const char* software : {"llvmpipe", "softpipe", "SwiftShader", "swrast"})
        if (renderer.find(software) != std::string::npos) return true;
    return false;
}

bool GpuLimits::computePassesFaster() const {
    const double fragment = fillGBps(SurfaceFormat::Color, false);
    return fragment > 0 && computeWriteGBps >= kComputePassesWhereFaster * fragment;
}

GpuLimits GpuLimits::ForDevice(GraphicsDevice& device, const std::string& cacheDir) {
    const std::string renderer = device.rendererName();
    const std::filesystem::path file =
        std::filesystem::path(cacheFolder(cacheDir)) /
        ("gpu-limits-" + std::to_string(std::hash<std::string>{}(renderer)) + ".txt");
    if (std::ifstream in{file}) {
        std::stringstream text;
        text << in.rdbuf();
        GpuLimits cached;
        if (fromText(text.str(), cached) && cached.renderer == renderer) return cached;
    }
    // A software rasteriser (OSMesa's llvmpipe) draws a 2048-square target in tens of ms: a small probe.
    GpuLimits limits = softwareRenderer(renderer) ? Measure(device, 256, 2) : Measure(device);
    std::error_code ec;
    std::filesystem::create_directories(file.parent_path(), ec);
    std::ofstream(file) << limits.toText();  // a cache: a folder we cannot write only costs a re-measure
    return limits;
}

}  // namespace fxport
