// Double-precision vector and matrix math for the CPU references (reference/), with HLSL's
// meaning: row vectors, mul(v, M) = sum_i v[i] * M[i][*] (XNA's layout, M[0] = M11..M14), frac,
// lerp, saturate, reflect as the HLSL intrinsics define them. Independent of fxport's float math:
// matrices that the runtime receives are converted once (toM4 in render_harness.h) and used here
// in double.
#pragma once

#include <algorithm>
#include <cmath>

namespace fxport::reference {

struct V2 {
    double x = 0, y = 0;
};
struct V3 {
    double x = 0, y = 0, z = 0;
};
struct V4 {
    double x = 0, y = 0, z = 0, w = 0;
    double operator[](int i) const { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
    double& operator[](int i) { return i == 0 ? x : i == 1 ? y : i == 2 ? z : w; }
    V3 xyz() const { return {x, y, z}; }
};

inline V2 operator+(V2 a, V2 b) { return {a.x + b.x, a.y + b.y}; }
inline V2 operator-(V2 a, V2 b) { return {a.x - b.x, a.y - b.y}; }
inline V2 operator*(V2 a, double s) { return {a.x * s, a.y * s}; }
inline V2 operator*(V2 a, V2 b) { return {a.x * b.x, a.y * b.y}; }

inline V3 operator+(V3 a, V3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3 operator-(V3 a, V3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3 operator-(V3 a) { return {-a.x, -a.y, -a.z}; }
inline V3 operator*(V3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline V3 operator*(double s, V3 a) { return a * s; }
inline V3 operator*(V3 a, V3 b) { return {a.x * b.x, a.y * b.y, a.z * b.z}; }
inline V3 operator/(V3 a, double s) { return {a.x / s, a.y / s, a.z / s}; }

inline V4 operator+(V4 a, V4 b) { return {a.x + b.x, a.y + b.y, a.z + b.z, a.w + b.w}; }
inline V4 operator-(V4 a, V4 b) { return {a.x - b.x, a.y - b.y, a.z - b.z, a.w - b.w}; }
inline V4 operator*(V4 a, double s) { return {a.x * s, a.y * s, a.z * s, a.w * s}; }
inline V4 operator*(V4 a, V4 b) { return {a.x * b.x, a.y * b.y, a.z * b.z, a.w * b.w}; }
inline V4 operator/(V4 a, double s) { return {a.x / s, a.y / s, a.z / s, a.w / s}; }
inline V4 splat(double s) { return {s, s, s, s}; }

inline double dot(V3 a, V3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3 cross(V3 a, V3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double length(V3 a) { return std::sqrt(dot(a, a)); }
inline V3 normalize(V3 a) { return a / length(a); }
// HLSL reflect(i, n) = i - 2 * dot(i, n) * n.
inline V3 reflect(V3 i, V3 n) { return i - n * (2 * dot(i, n)); }
inline double saturate(double v) { return std::clamp(v, 0.0, 1.0); }
inline double frac(double v) { return v - std::floor(v); }
inline double lerp(double a, double b, double t) { return a + (b - a) * t; }
inline V4 lerp(V4 a, V4 b, double t) { return a + (b - a) * t; }
inline V3 lerp(V3 a, V3 b, double t) { return a + (b - a) * t; }

// A 4x4 matrix in XNA's layout: m[r][c] = M(r+1)(c+1); points are row vectors.
struct M4 {
    double m[4][4] = {};
    static M4 identity() {
        M4 r;
        for (int i = 0; i < 4; ++i) r.m[i][i] = 1;
        return r;
    }
};

// HLSL mul(v, M) for a float4 row vector.
inline V4 mul(V4 v, const M4& a) {
    V4 r;
    for (int j = 0; j < 4; ++j) r[j] = v.x * a.m[0][j] + v.y * a.m[1][j] + v.z * a.m[2][j] + v.w * a.m[3][j];
    return r;
}
// HLSL mul(float3, (float3x3)M): the upper-left 3x3 (also what fxc and glslang make of
// mul(float3, float4x4): the matrix is truncated to the vector's size).
inline V3 mul3(V3 v, const M4& a) {
    return {v.x * a.m[0][0] + v.y * a.m[1][0] + v.z * a.m[2][0], v.x * a.m[0][1] + v.y * a.m[1][1] + v.z * a.m[2][1],
            v.x * a.m[0][2] + v.y * a.m[1][2] + v.z * a.m[2][2]};
}
// a * b in XNA's sense (apply a, then b).
inline M4 operator*(const M4& a, const M4& b) {
    M4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            double s = 0;
            for (int k = 0; k < 4; ++k) s += a.m[i][k] * b.m[k][j];
            r.m[i][j] = s;
        }
    return r;
}
// Gauss-Jordan with partial pivoting (double).
inline M4 inverse(const M4& a) {
    double t[4][8];
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            t[i][j] = a.m[i][j];
            t[i][j + 4] = i == j ? 1 : 0;
        }
    for (int c = 0; c < 4; ++c) {
        int p = c;
        for (int r = c + 1; r < 4; ++r)
            if (std::fabs(t[r][c]) > std::fabs(t[p][c])) p = r;
        for (int j = 0; j < 8; ++j) std::swap(t[c][j], t[p][j]);
        double d = t[c][c];
        for (int j = 0; j < 8; ++j) t[c][j] /= d;
        for (int r = 0; r < 4; ++r)
            if (r != c) {
                double f = t[r][c];
                for (int j = 0; j < 8; ++j) t[r][j] -= f * t[c][j];
            }
    }
    M4 r;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) r.m[i][j] = t[i][j + 4];
    return r;
}

inline V4 point(V3 p) { return {p.x, p.y, p.z, 1}; }

}  // namespace fxport::reference
