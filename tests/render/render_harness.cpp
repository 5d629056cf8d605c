#include "render_harness.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <iostream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace fxport::render_test {

M4 toM4(const Matrix& m) {
    M4 r;
    const float* p = m.data();
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = double(p[i * 4 + j]);
    return r;
}
V3 toV3(Vector3 v) { return {double(v.X), double(v.Y), double(v.Z)}; }
V4 toV4(Vector4 v) { return {double(v.X), double(v.Y), double(v.Z), double(v.W)}; }
V2 toV2(Vector2 v) { return {double(v.X), double(v.Y)}; }

TexelFormat texelFormat(SurfaceFormat f) {
    switch (f) {
    case SurfaceFormat::Color: return TexelFormat::Unorm8;
    case SurfaceFormat::Rgba64: return TexelFormat::Unorm16;
    case SurfaceFormat::Single:
    case SurfaceFormat::Vector2:
    case SurfaceFormat::Vector4: return TexelFormat::Float32;
    default: throw std::runtime_error("render tests: surface format not used by the demo");
    }
}

int channelCount(SurfaceFormat f) {
    switch (f) {
    case SurfaceFormat::Single: return 1;
    case SurfaceFormat::Vector2: return 2;
    default: return 4;
    }
}

double formatBound(TexelFormat f, double value) {
    switch (f) {
    case TexelFormat::Unorm8: return 1.0 / 255;
    case TexelFormat::Unorm16: return 1.0 / 65535;
    default: return 1e-5 * std::fabs(value) + 1e-30;
    }
}

namespace {

double lsb(TexelFormat f) { return f == TexelFormat::Unorm8 ? 1.0 / 255 : f == TexelFormat::Unorm16 ? 1.0 / 65535 : 0; }

double store(TexelFormat f, double v) {
    switch (f) {
    case TexelFormat::Unorm8: return std::round(std::clamp(v, 0.0, 1.0) * 255) / 255;
    case TexelFormat::Unorm16: return std::round(std::clamp(v, 0.0, 1.0) * 65535) / 65535;
    default: return double(float(v));
    }
}

SurfaceFormat surfaceOf(const CpuTexture& t) {
    switch (t.format) {
    case TexelFormat::Unorm8: return SurfaceFormat::Color;
    case TexelFormat::Unorm16: return SurfaceFormat::Rgba64;
    default: return t.channels == 1 ? SurfaceFormat::Single : t.channels == 2 ? SurfaceFormat::Vector2 : SurfaceFormat::Vector4;
    }
}

// Packs texels as SetData/GetData exchange them for the format.
std::vector<unsigned char> pack(const CpuTexture& t) {
    std::vector<unsigned char> bytes;
    for (const V4& v : t.texels)
        for (int c = 0; c < t.channels; ++c) {
            if (t.format == TexelFormat::Unorm8) {
                bytes.push_back(static_cast<unsigned char>(std::lround(v[c] * 255)));
            } else if (t.format == TexelFormat::Unorm16) {
                auto u = static_cast<std::uint16_t>(std::lround(v[c] * 65535));
                bytes.push_back(static_cast<unsigned char>(u & 0xff));
                bytes.push_back(static_cast<unsigned char>(u >> 8));
            } else {
                float f = float(v[c]);
                const auto* p = reinterpret_cast<const unsigned char*>(&f);
                bytes.insert(bytes.end(), p, p + 4);
            }
        }
    return bytes;
}

CpuTexture unpack(int w, int h, SurfaceFormat f, const std::vector<unsigned char>& bytes) {
    CpuTexture t(w, h, texelFormat(f), channelCount(f));
    std::size_t o = 0;
    for (V4& v : t.texels) {
        v = {1, 1, 1, 1};
        for (int c = 0; c < t.channels; ++c) {
            if (t.format == TexelFormat::Unorm8) {
                v[c] = bytes[o++] / 255.0;
            } else if (t.format == TexelFormat::Unorm16) {
                unsigned u = unsigned(bytes[o]) | (unsigned(bytes[o + 1]) << 8);
                o += 2;
                v[c] = u / 65535.0;
            } else {
                float x;
                std::copy(bytes.begin() + std::ptrdiff_t(o), bytes.begin() + std::ptrdiff_t(o + 4), reinterpret_cast<unsigned char*>(&x));
                o += 4;
                v[c] = double(x);
            }
        }
    }
    return t;
}

}  // namespace

CpuTexture quantize(int width, int height, SurfaceFormat f, const std::function<V4(int x, int y)>& values) {
    CpuTexture t(width, height, texelFormat(f), channelCount(f));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            V4 v = values(x, y);
            V4& out = t.at(x, y);
            for (int c = 0; c < 4; ++c) out[c] = c < t.channels ? store(t.format, v[c]) : 1.0;
        }
    return t;
}

void upload(Texture2D& texture, const CpuTexture& data) {
    if (surfaceOf(data) != texture.Format()) throw std::runtime_error("upload: format mismatch");
    std::vector<unsigned char> bytes = pack(data);
    texture.setData(0, nullptr, bytes.data(), bytes.size());
}

void upload(TextureCube& texture, CubeMapFace face, const CpuTexture& data) {
    if (surfaceOf(data) != texture.Format()) throw std::runtime_error("upload: format mismatch");
    std::vector<unsigned char> bytes = pack(data);
    texture.setData(face, bytes.data(), bytes.size());
}

CpuTexture readBack(const Texture2D& texture) {
    std::vector<unsigned char> bytes(std::size_t(texture.Width()) * std::size_t(texture.Height()) *
                                     std::size_t(bytesPerPixel(texture.Format())));
    texture.getData(0, bytes.data(), bytes.size());
    return unpack(texture.Width(), texture.Height(), texture.Format(), bytes);
}

CpuTexture readBack(const TextureCube& texture, CubeMapFace face) {
    std::vector<unsigned char> bytes(std::size_t(texture.Size()) * std::size_t(texture.Size()) *
                                     std::size_t(bytesPerPixel(texture.Format())));
    texture.getData(face, bytes.data(), bytes.size());
    return unpack(texture.Size(), texture.Size(), texture.Format(), bytes);
}

RefImage referenceImage(int width, int height, SurfaceFormat format, bool rasterSlack, const ReferencePixel& pixel) {
    RefImage ref;
    ref.width = width;
    ref.height = height;
    ref.format = format;
    EvalOptions options;
    options.rasterSlack = rasterSlack;
    if (texelFormat(format) != TexelFormat::Float32) {
        options.clampLo = 0;
        options.clampHi = 1;
    }
    ref.pixels.reserve(std::size_t(width) * std::size_t(height));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            PixelPos p{x, y, width, height};
            ref.pixels.push_back(evaluatePixel([&](Eval& ev) { return pixel(ev, p); }, options));
        }
    return ref;
}

CpuTexture asInput(const RefImage& ref) {
    TexelFormat f = texelFormat(ref.format);
    CpuTexture t(ref.width, ref.height, f, channelCount(ref.format));
    t.tol.resize(t.texels.size());
    for (std::size_t i = 0; i < ref.pixels.size(); ++i) {
        const PixelResult& r = ref.pixels[i];
        for (int c = 0; c < 4; ++c) {
            if (c >= t.channels) {
                t.texels[i][c] = 1;
                continue;
            }
            double mid = (r.lo[c] + r.hi[c]) / 2;
            t.texels[i][c] = store(f, mid);
            t.tol[i][c] = r.exact ? lsb(f) : (r.hi[c] - r.lo[c]) / 2 + ref.boundScale * formatBound(f, mid) + r.slack[c];
        }
    }
    return t;
}

namespace {

struct Counts {
    long samples = 0, failures = 0, slackSamples = 0, ambiguous = 0, wide = 0;
    double maxError = 0, sumSquares = 0, maxAllowed = 0, maxSlack = 0, maxRel = 0;
    std::vector<double> allowed;
    std::string text;
};

Counts count(const CpuTexture& gpu, const RefImage& ref, int channels, int shift) {
    Counts k;
    TexelFormat f = texelFormat(ref.format);
    std::ostringstream text;
    for (int y = 0; y < ref.height; ++y)
        for (int x = 0; x < ref.width; ++x) {
            const PixelResult& r = ref.at(x, y);
            const V4& gv = gpu.at(std::max(0, x - shift), y);
            bool ambiguous = r.leaves > 1, wide = false;
            for (int ch = 0; ch < channels; ++ch) {
                ambiguous = ambiguous || r.lo[ch] != r.hi[ch];
                double g = gv[ch];
                double e = std::max({0.0, r.lo[ch] - g, g - r.hi[ch]});
                if (std::isnan(g)) e = std::numeric_limits<double>::infinity();
                double mid = (r.lo[ch] + r.hi[ch]) / 2;
                double bound = ref.boundScale * formatBound(f, mid);
                double allowed = bound + r.slack[ch];
                ++k.samples;
                k.sumSquares += e * e;
                k.maxError = std::max(k.maxError, e);
                if (e > 0 && f == TexelFormat::Float32) k.maxRel = std::max(k.maxRel, e / std::max(std::fabs(mid), 1e-30));
                if (r.hi[ch] - r.lo[ch] > bound) wide = true;
                k.maxAllowed = std::max(k.maxAllowed, allowed);
                k.maxSlack = std::max(k.maxSlack, r.slack[ch]);
                k.allowed.push_back(allowed);
                if (r.slack[ch] > bound) ++k.slackSamples;
                if (!(e <= allowed)) {
                    if (k.failures < 12) {
                        char line[256];
                        std::snprintf(line, sizeof line,
                                      "  pixel (%d,%d) channel %d: GPU %.7g, reference [%.7g, %.7g], |error| %.3g > bound %.3g\n", x, y,
                                      ch, g, r.lo[ch], r.hi[ch], e, allowed);
                        text << line;
                    }
                    ++k.failures;
                }
            }
            if (ambiguous) ++k.ambiguous;
            if (wide) ++k.wide;
        }
    k.text = text.str();
    return k;
}

}  // namespace

Comparison compare(const std::string& pass, const CpuTexture& gpu, const RefImage& ref, int maxChannels) {
    if (gpu.width != ref.width || gpu.height != ref.height) throw std::runtime_error(pass + ": size mismatch");
    int channels = std::min(channelCount(ref.format), maxChannels);
    Counts k = count(gpu, ref, channels, 0);
    Comparison c;
    c.pass = pass;
    c.samples = k.samples;
    c.maxError = k.maxError;
    c.rmsError = std::sqrt(k.sumSquares / double(std::max<long>(k.samples, 1)));
    c.maxAllowed = k.maxAllowed;
    c.maxSlack = k.maxSlack;
    c.slackSamples = k.slackSamples;
    c.ambiguousPixels = k.ambiguous;
    c.wideRangePixels = k.wide;
    c.failures = k.failures;
    c.failureText = k.text;
    c.maxRelError = k.maxRel;
    std::sort(k.allowed.begin(), k.allowed.end());
    c.medianAllowed = k.allowed[k.allowed.size() / 2];
    c.p95Allowed = k.allowed[k.allowed.size() * 95 / 100];
    c.shiftedFailureFraction = double(count(gpu, ref, channels, 1).failures) / double(k.samples);
    // What a shift could reveal: samples whose reference differs from the left neighbour's by more
    // than the bound.
    long visible = 0;
    TexelFormat f = texelFormat(ref.format);
    for (int y = 0; y < ref.height; ++y)
        for (int x = 1; x < ref.width; ++x)
            for (int ch = 0; ch < channels; ++ch) {
                const PixelResult &r = ref.at(x, y), &l = ref.at(x - 1, y);
                double mid = (r.lo[ch] + r.hi[ch]) / 2, left = (l.lo[ch] + l.hi[ch]) / 2;
                if (std::fabs(mid - left) > ref.boundScale * formatBound(f, mid) + r.slack[ch] + (r.hi[ch] - r.lo[ch]) / 2) ++visible;
            }
    c.shiftVisibleFraction = double(visible) / double(k.samples);
    return c;
}

void report(const Comparison& c) {
    char line[512];
    std::snprintf(line, sizeof line,
                  "[render] %-22s max %-9.3g rms %-9.3g (rel %-7.2g) bound median %-8.3g p95 %-8.3g max %-8.3g | "
                  "ambiguous px %4ld (wider than bound %4ld) | 1-px shift fails %4.1f%% (visible %4.1f%%)\n",
                  c.pass.c_str(), c.maxError, c.rmsError, c.maxRelError, c.medianAllowed, c.p95Allowed, c.maxAllowed,
                  c.ambiguousPixels, c.wideRangePixels, 100.0 * c.shiftedFailureFraction, 100.0 * c.shiftVisibleFraction);
    std::cout << line << std::flush;
    ::testing::Test::RecordProperty(c.pass + ".max_error", std::to_string(c.maxError));
    ::testing::Test::RecordProperty(c.pass + ".rms_error", std::to_string(c.rmsError));
    ::testing::Test::RecordProperty(c.pass + ".max_relative_error", std::to_string(c.maxRelError));
    ::testing::Test::RecordProperty(c.pass + ".median_bound", std::to_string(c.medianAllowed));
    ::testing::Test::RecordProperty(c.pass + ".max_bound", std::to_string(c.maxAllowed));
}

}  // namespace fxport::render_test
