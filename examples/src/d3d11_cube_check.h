// d3d11_cube's scene in numbers (the cube's faces, the matrices, the texture, the light) and its
// --check: a CPU ray cast per pixel in double precision, compared with the frame D3D11 drew.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace cube {

struct Vec3 {
    double x = 0, y = 0, z = 0;
};
inline Vec3 operator+(Vec3 a, Vec3 b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline Vec3 operator*(Vec3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
inline double dot(Vec3 a, Vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

// A face of the cube [-1, 1]^3: normal n, and u (right) and v (up) as seen from outside.
struct Face {
    Vec3 n, u, v;
    // The point at texture coordinates (s, t): s along u, t down v (texture row 0 at the top).
    Vec3 pointAt(double s, double t) const { return n + u * (2 * s - 1) + v * (1 - 2 * t); }
};
const std::vector<Face>& faces();

// Row-major 4x4 (XMFLOAT4X4's order); points are row vectors: p' = p * M.
struct Matrix4 {
    float m[16];
};
Matrix4 world(double seconds);              // XMMatrixRotationY(seconds)
Matrix4 view();                             // XMMatrixLookAtLH(eye (0,3,-6), at (0,1,0), up (0,1,0))
Matrix4 projection(double aspect);          // XMMatrixPerspectiveFovLH(pi/4, aspect, 0.01, 100)
Matrix4 transpose(const Matrix4& m);        // XMMatrixTranspose: what a column_major cbuffer holds

constexpr int kTextureSize = 4;
std::uint32_t texel(int x, int y);          // RGBA8 (R in the low byte)
inline constexpr double kLightDirection[4] = {0.36, -0.48, 0.8, 0};  // unit length, towards the surface
inline constexpr double kAmbient = 0.2;

struct Check {
    int checked = 0, skipped = 0, mismatched = 0;
    std::string firstMismatch;
    bool passed() const { return mismatched == 0 && checked > 0; }
    std::string summary() const;
};
// `rgba`: the frame, top row first. Pixels on an edge (of the cube, a face or a texel: the samples
// 0.45 pixel around the centre disagree) are skipped; the rest must match within 3/255.
Check checkFrame(const std::vector<std::uint8_t>& rgba, int width, int height, double seconds, const float meshColor[4]);

}  // namespace cube
