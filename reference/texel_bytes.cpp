#include "reference/texel_bytes.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace fxport::reference {

double lsb(TexelFormat f) { return f == TexelFormat::Unorm8 ? 1.0 / 255 : f == TexelFormat::Unorm16 ? 1.0 / 65535 : 0; }

double store(TexelFormat f, double v) {
    switch (f) {
    case TexelFormat::Unorm8: return std::round(std::clamp(v, 0.0, 1.0) * 255) / 255;
    case TexelFormat::Unorm16: return std::round(std::clamp(v, 0.0, 1.0) * 65535) / 65535;
    default: return double(float(v));
    }
}

double formatBound(TexelFormat f, double value) {
    switch (f) {
    case TexelFormat::Unorm8: return 1.0 / 255;
    case TexelFormat::Unorm16: return 1.0 / 65535;
    default: return 1e-5 * std::fabs(value) + 1e-30;
    }
}

std::vector<unsigned char> packTexels(const CpuTexture& t) {
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

CpuTexture unpackTexels(int width, int height, TexelFormat f, int channels, const std::vector<unsigned char>& bytes) {
    CpuTexture t(width, height, f, channels);
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

}  // namespace fxport::reference
