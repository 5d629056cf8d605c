#include "report/lighting2d_reference.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace fxport::report {

namespace {

// Distance from `from` along the unit direction (dx, dy) to where the line enters the first
// caster texel, at most `limit` (infinity when none is met). Amanatides & Woo's grid walk: every
// texel the line passes through, in order.
double firstOccluder(const std::vector<bool>& solid, int W, int H, double fx, double fy, double dx, double dy, double limit) {
    int x = int(std::floor(fx)), y = int(std::floor(fy));
    const int stepX = dx > 0 ? 1 : -1, stepY = dy > 0 ? 1 : -1;
    const double inf = std::numeric_limits<double>::infinity();
    double tMaxX = dx != 0 ? ((dx > 0 ? x + 1 - fx : fx - x) / std::fabs(dx)) : inf;
    double tMaxY = dy != 0 ? ((dy > 0 ? y + 1 - fy : fy - y) / std::fabs(dy)) : inf;
    const double tDeltaX = dx != 0 ? 1 / std::fabs(dx) : inf, tDeltaY = dy != 0 ? 1 / std::fabs(dy) : inf;
    double t = 0;
    while (t <= limit) {
        if (x < 0 || y < 0 || x >= W || y >= H) return inf;  // left the screen: nothing further
        if (solid[std::size_t(y) * std::size_t(W) + std::size_t(x)]) return t;
        if (tMaxX < tMaxY) {
            t = tMaxX;
            tMaxX += tDeltaX;
            x += stepX;
        } else {
            t = tMaxY;
            tMaxY += tDeltaY;
            y += stepY;
        }
    }
    return inf;
}

}  // namespace

std::vector<double> lighting2dReference(const _2DLightingSystem::LightRenderer& r, const std::vector<Color>& background,
                                        const std::vector<Color>& casters, int W, int H) {
    const std::size_t n = std::size_t(W) * std::size_t(H);
    std::vector<bool> solid(n);
    for (std::size_t i = 0; i < n; ++i) solid[i] = casters[i].A / 255.0 >= 0.01;
    std::vector<double> light(n * 3, 0.0);
    const double centre = 1.0 / 256.0;
    const double bias = r.lightBias;

    // One light: `amount(px, py, dist)` is the light map value before visibility (or < 0: outside).
    auto addLight = [&](const _2DLightingSystem::Light& l, auto amount) {
        const Vector4 c = l.color.ToVector4();
        const double lx = l.Position.X, ly = l.Position.Y;
        for (int y = 0; y < H; ++y)
            for (int x = 0; x < W; ++x) {
                const double px = x + centre, py = y + centre;
                const double dx = px - lx, dy = py - ly, dist = std::hypot(dx, dy);
                if (dist - bias >= l.radius) continue;  // the shaders' pixDist - Bias < Radius
                double a = amount(dx, dy, dist);
                if (a <= 0) continue;
                if (dist > 0 && dist - bias >= firstOccluder(solid, W, H, lx, ly, dx / dist, dy / dist, dist)) continue;
                a = std::min(a, 1.0);  // the light's own map (Color) clamps
                double* out = &light[(std::size_t(y) * std::size_t(W) + std::size_t(x)) * 3];
                out[0] = std::min(1.0, out[0] + a * c.X);  // additive into the Color light map
                out[1] = std::min(1.0, out[1] + a * c.Y);
                out[2] = std::min(1.0, out[2] + a * c.Z);
            }
    };
    for (const auto& s : r.spotLights) {
        const double center = s.GetBiasedAngle(), bias2pi = s.GetAngleBias();
        const double halfInner = s.innerAngle / 2.0, halfOuter = s.outerAngle / 2.0;
        addLight(s, [&](double dx, double dy, double dist) {
            if (dist == 0) return -1.0;
            double angle = std::acos(std::clamp(dy / dist, -1.0, 1.0));  // dot((0, 1), normalize(lightToPix))
            if (dx < 0) angle = -angle;
            if (angle < 0) angle += bias2pi;
            const double diff = std::fabs(angle - center);
            if (diff >= halfOuter) return -1.0;
            const double cone = diff < halfInner ? 1.0 : std::clamp((halfOuter - diff) / (halfOuter - halfInner), 0.0, 1.0);
            return (1 - dist / s.radius) * s.Power * cone;
        });
    }
    for (const auto& p : r.pointLights)
        addLight(p, [&](double, double, double dist) { return (1 - dist / p.radius) * p.Power; });

    const double minLight = r.minLight;
    std::vector<double> rgb(n * 3);
    for (std::size_t i = 0; i < n; ++i) {
        const Color b = background[i], c = casters[i];
        const double bg[3] = {b.R / 255.0, b.G / 255.0, b.B / 255.0}, cs[3] = {c.R / 255.0, c.G / 255.0, c.B / 255.0};
        const double alpha = c.A / 255.0;
        for (int k = 0; k < 3; ++k) {
            const double lit = bg[k] * (light[i * 3 + std::size_t(k)] * (1 - minLight) + minLight);
            rgb[i * 3 + std::size_t(k)] = std::clamp(cs[k] + (1 - alpha) * lit, 0.0, 1.0);  // premultiplied over
        }
    }
    return rgb;
}

}  // namespace fxport::report
