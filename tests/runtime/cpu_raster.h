// A small double-precision CPU rasteriser for the stock-effect and Model pixel tests: vertices go
// through a test-written "vertex shader", triangles are culled (XNA: counter-clockwise on screen
// culled), depth-tested, and each pixel's varyings are interpolated perspective-correctly at the
// D3D9 sample point (pixel (i, j) samples screen position (i, j): fxport gives SM <= 3 vertex
// shaders D3D9's pixel centres), then a test-written "pixel shader" gives the expected colour.
//
// Which pixels can be compared: attributes of shared vertices are continuous across inner edges,
// so which of two neighbouring triangles the GPU picks there does not matter; what does matter is
// coverage at silhouettes and which surface is in front where two overlap. A pixel is compared
// only when the same surface is front-most at its sample point and at the 8 points one pixel
// around it (or no surface covers any of the 9: background).
#pragma once

#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "fxport/math.h"

namespace fxport::stock_test {

struct D3 {
    double x = 0, y = 0, z = 0;
};
struct D4 {
    double x = 0, y = 0, z = 0, w = 0;
    D3 xyz() const { return {x, y, z}; }
};
inline D3 operator+(D3 a, D3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline D3 operator-(D3 a) { return {-a.x, -a.y, -a.z}; }
inline D3 operator*(D3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline D3 operator*(D3 a, D3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline D4 operator+(D4 a, D4 b) { return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w}; }
inline D4 operator*(D4 a, double s) { return {a.x * s, a.y * s, a.z * s, a.w * s}; }
inline D4 operator*(D4 a, D4 b) { return {a.x * b.x, a.y * b.y, a.z * b.z, a.w * b.w}; }
inline double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double dot(D4 a, D4 b) { return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w; }
inline D3 normalize(D3 a) { return a * (1.0 / std::sqrt(dot(a, a))); }
inline double saturate(double v) { return v < 0 ? 0 : v > 1 ? 1 : v; }
inline D3 lerp(D3 a, D3 b, double t) { return a + (b - a) * t; }
inline D3 reflect(D3 i, D3 n) { return i - n * (2 * dot(i, n)); }
inline D3 toD3(Vector3 v) { return {v.X, v.Y, v.Z}; }
inline D4 toD4(Vector4 v) { return {v.X, v.Y, v.Z, v.W}; }

// XNA layout: m[r][c] = M(r+1)(c+1), row vectors.
struct DMat {
    double m[4][4] = {};
};
inline DMat toDMat(const Matrix& a) {
    const float* f = &a.M11;
    DMat r;
    for (int i = 0; i < 16; ++i) r.m[i / 4][i % 4] = f[i];
    return r;
}
inline DMat operator*(const DMat& a, const DMat& b) {
    DMat r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            for (int k = 0; k < 4; ++k) r.m[i][j] += a.m[i][k] * b.m[k][j];
    return r;
}
inline D4 mul(D4 v, const DMat& a) {
    double in[4] = {v.x, v.y, v.z, v.w}, out[4] = {};
    for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 4; ++k) out[j] += in[k] * a.m[k][j];
    return {out[0], out[1], out[2], out[3]};
}
inline D3 mul3(D3 v, const DMat& a) {
    D4 r = mul(D4{v.x, v.y, v.z, 0}, a);
    return r.xyz();
}
DMat inverse(const DMat& a);
DMat transpose(const DMat& a);

struct RasterVertex {
    D4 clip;                       // clip-space position
    std::vector<double> varyings;  // interpolated perspective-correctly
};

enum class PixelKind : std::uint8_t { Background, Covered, Unsure };

struct RasterPixel {
    PixelKind kind = PixelKind::Background;
    std::vector<double> varyings;  // Covered only
    int surface = -1;
};

// `surface[t]` names the surface triangle t belongs to (empty: one surface). Clockwise triangles
// (on screen, y down) are front faces; counter-clockwise ones are culled.
std::vector<RasterPixel> rasterize(int width, int height, const std::vector<RasterVertex>& vertices,
                                   const std::vector<std::uint32_t>& indices, const std::vector<int>& surface = {});

}  // namespace fxport::stock_test
