#include "light_textures.h"

#include <algorithm>
#include <cmath>

#include "rng.h"
#include "vec.h"

namespace fxport::content {

namespace {

float SmoothStep(float edge0, float edge1, float x) {
    const float t = std::clamp((x - edge0) / (edge1 - edge0), 0.0f, 1.0f);
    return t * t * (3.0f - 2.0f * t);
}

Rgba Grey(float value) { return {value, value, value, 1.0f}; }

}  // namespace

Image MakeSpotCookie(int size) {
    Image out(size, size);
    const float half = static_cast<float>(size) * 0.5f;
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float dx = (static_cast<float>(x) + 0.5f - half) / half;
            const float dy = (static_cast<float>(y) + 0.5f - half) / half;
            const float r = std::sqrt(dx * dx + dy * dy);
            const float falloff = 1.0f - SmoothStep(0.45f, 0.95f, r);
            const float rings = 0.82f + 0.18f * std::cos(2.0f * kPi * 5.0f * r);
            const float hotSpot = 0.15f * (1.0f - SmoothStep(0.0f, 0.3f, r));
            out.Set(x, y, Grey(std::min(1.0f, falloff * rings + hotSpot * falloff)));
        }
    }
    return out;
}

Image MakeSquareCookie(int size) {
    Image out(size, size);
    const float s = static_cast<float>(size) / 256.0f;
    const float margin = 12.0f * s;     // dark border, so LinearClamp repeats black beyond the edge
    const float frame = 10.0f * s;      // window frame inside the margin
    const float mullionHalf = 5.0f * s; // the cross between the panes
    const float soft = 1.5f * s;
    const float fs = static_cast<float>(size);
    // Signed distance (texels, positive inside) to the nearest pane along one axis.
    auto paneDistance = [&](float p) {
        const float lo = margin + frame;
        const float hi = fs - margin - frame;
        const float mid = fs * 0.5f;
        const float first = std::min(p - lo, (mid - mullionHalf) - p);
        const float second = std::min(p - (mid + mullionHalf), hi - p);
        return std::max(first, second);
    };
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            const float d = std::min(paneDistance(static_cast<float>(x) + 0.5f),
                                     paneDistance(static_cast<float>(y) + 0.5f));
            out.Set(x, y, Grey(SmoothStep(-soft, soft, d)));
        }
    }
    return out;
}

Image MakeRandomNormals(int size, std::uint64_t seed) {
    Image out(size, size);
    SplitMix64 rng(seed);
    for (int y = 0; y < size; ++y) {
        for (int x = 0; x < size; ++x) {
            // Uniform on the unit sphere: z uniform in [-1, 1], azimuth uniform.
            const float z = 2.0f * rng.NextUnit() - 1.0f;
            const float phi = 2.0f * kPi * rng.NextUnit();
            const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
            const Vec3 n{r * std::cos(phi), r * std::sin(phi), z};
            out.Set(x, y, {n.x * 0.5f + 0.5f, n.y * 0.5f + 0.5f, n.z * 0.5f + 0.5f, 1.0f});
        }
    }
    return out;
}

}  // namespace fxport::content
