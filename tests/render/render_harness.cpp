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

namespace {

SurfaceFormat surfaceOf(const CpuTexture& t) {
    switch (t.format) {
    case TexelFormat::Unorm8: return SurfaceFormat::Color;
    case TexelFormat::Unorm16: return SurfaceFormat::Rgba64;
    default: return t.channels == 1 ? SurfaceFormat::Single : t.channels == 2 ? SurfaceFormat::Vector2 : SurfaceFormat::Vector4;
    }
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
    std::vector<unsigned char> bytes = packTexels(data);
    texture.setData(0, nullptr, bytes.data(), bytes.size());
}

void upload(TextureCube& texture, CubeMapFace face, const CpuTexture& data) {
    if (surfaceOf(data) != texture.Format()) throw std::runtime_error("upload: format mismatch");
    std::vector<unsigned char> bytes = packTexels(data);
    texture.setData(face, bytes.data(), bytes.size());
}

CpuTexture readBack(const Texture2D& texture) {
    std::vector<unsigned char> bytes(std::size_t(texture.Width()) * std::size_t(texture.Height()) *
                                     std::size_t(bytesPerPixel(texture.Format())));
    texture.getData(0, bytes.data(), bytes.size());
    return unpackTexels(texture.Width(), texture.Height(), texelFormat(texture.Format()), channelCount(texture.Format()), bytes);
}

CpuTexture readBack(const TextureCube& texture, CubeMapFace face) {
    std::vector<unsigned char> bytes(std::size_t(texture.Size()) * std::size_t(texture.Size()) *
                                     std::size_t(bytesPerPixel(texture.Format())));
    texture.getData(face, bytes.data(), bytes.size());
    return unpackTexels(texture.Size(), texture.Size(), texelFormat(texture.Format()), channelCount(texture.Format()), bytes);
}

RefImage referenceImage(int width, int height, SurfaceFormat format, bool rasterSlack, const ReferencePixel& pixel) {
    return evaluateImage(width, height, texelFormat(format), channelCount(format), rasterSlack,
                         [&](Eval& ev, int x, int y) { return pixel(ev, PixelPos{x, y, width, height}); });
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
