// d3d11_cube's scene numbers and its CPU check (d3d11_cube_check.h).
#include "d3d11_cube_check.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace cube {

namespace {

constexpr double kPi = 3.14159265358979323846;
const Vec3 kEye{0, 3, -6}, kAt{0, 1, 0}, kUp{0, 1, 0};
constexpr double kFovY = kPi / 4;

Vec3 normalize(Vec3 a) { return a * (1 / std::sqrt(dot(a, a))); }
Vec3 cross(Vec3 a, Vec3 b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
// p * XMMatrixRotationY(a): (x cos + z sin, y, -x sin + z cos).
Vec3 rotateY(Vec3 p, double a) { return {p.x * std::cos(a) + p.z * std::sin(a), p.y, -p.x * std::sin(a) + p.z * std::cos(a)}; }

struct Hit {
    int face = -1;  // -1: the background
    int texelX = 0, texelY = 0;
    double rgba[4] = {0, 0, 0, 0};
    bool sameAs(const Hit& o) const { return face == o.face && texelX == o.texelX && texelY == o.texelY; }
};

// The colour the pixel shader computes where the ray through (px, py) meets the cube.
Hit trace(double px, double py, int width, int height, double seconds, const float meshColor[4]) {
    const double aspect = double(width) / height, h = std::tan(kFovY / 2);
    const double nx = px / width * 2 - 1, ny = 1 - py / height * 2;
    const Vec3 forward = normalize(kAt + kEye * -1), right = normalize(cross(kUp, forward)), up = cross(forward, right);
    const Vec3 dir = right * (nx * h * aspect) + up * (ny * h) + forward;
    // Into the cube's space (its world matrix is a rotation about y).
    const Vec3 o = rotateY(kEye, -seconds), d = rotateY(dir, -seconds);
    double tNear = -1e30, tFar = 1e30;
    int axis = -1;
    const double os[3] = {o.x, o.y, o.z}, ds[3] = {d.x, d.y, d.z};
    for (int a = 0; a < 3; ++a) {
        if (std::abs(ds[a]) < 1e-12) {
            if (std::abs(os[a]) > 1) return {};
            continue;
        }
        double t0 = (-1 - os[a]) / ds[a], t1 = (1 - os[a]) / ds[a];
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > tNear) tNear = t0, axis = a;
        tFar = std::min(tFar, t1);
    }
    if (tNear > tFar || tNear <= 0 || axis < 0) return {};
    const Vec3 p = o + d * tNear;
    const double ps[3] = {p.x, p.y, p.z};
    Hit hit;
    for (std::size_t f = 0; f < faces().size(); ++f) {
        const Vec3& n = faces()[f].n;
        const double ns[3] = {n.x, n.y, n.z};
        if (ns[axis] != 0 && (ns[axis] > 0) == (ps[axis] > 0)) hit.face = int(f);
    }
    const Face& face = faces()[std::size_t(hit.face)];
    const double s = (dot(p, face.u) + 1) / 2, t = (1 - dot(p, face.v)) / 2;
    hit.texelX = std::clamp(int(std::floor(s * kTextureSize)), 0, kTextureSize - 1);
    hit.texelY = std::clamp(int(std::floor(t * kTextureSize)), 0, kTextureSize - 1);
    const Vec3 normal = rotateY(face.n, seconds);
    const Vec3 light{kLightDirection[0], kLightDirection[1], kLightDirection[2]};
    const double diffuse = std::clamp(dot(normal, light * -1), 0.0, 1.0);
    const std::uint32_t c = texel(hit.texelX, hit.texelY);
    for (int i = 0; i < 4; ++i)
        hit.rgba[i] = std::min(1.0, double((c >> (8 * i)) & 0xff) / 255 * meshColor[i] * (kAmbient + diffuse));
    return hit;
}

}  // namespace

const std::vector<Face>& faces() {
    // u x v = -n: u to the right and v up as a viewer outside the face sees it (left-handed).
    static const std::vector<Face> all = {
        {{0, 0, -1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, 1}, {-1, 0, 0}, {0, 1, 0}}, {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
        {{-1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{0, 1, 0}, {1, 0, 0}, {0, 0, 1}},  {{0, -1, 0}, {1, 0, 0}, {0, 0, -1}},
    };
    return all;
}

Matrix4 world(double seconds) {
    const float c = float(std::cos(seconds)), s = float(std::sin(seconds));
    return {{c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, 0, 0, 0, 1}};
}

Matrix4 view() {
    const Vec3 z = normalize(kAt + kEye * -1), x = normalize(cross(kUp, z)), y = cross(z, x);
    return {{float(x.x), float(y.x), float(z.x), 0, float(x.y), float(y.y), float(z.y), 0, float(x.z), float(y.z), float(z.z), 0,
             float(-dot(x, kEye)), float(-dot(y, kEye)), float(-dot(z, kEye)), 1}};
}

Matrix4 projection(double aspect) {
    const double n = 0.01, f = 100, yScale = 1 / std::tan(kFovY / 2), xScale = yScale / aspect;
    return {{float(xScale), 0, 0, 0, 0, float(yScale), 0, 0, 0, 0, float(f / (f - n)), 1, 0, 0, float(-n * f / (f - n)), 0}};
}

Matrix4 transpose(const Matrix4& m) {
    Matrix4 t;
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) t.m[c * 4 + r] = m.m[r * 4 + c];
    return t;
}

std::uint32_t texel(int x, int y) {
    const bool light = (x + y) % 2 == 0;
    const std::uint32_t r = light ? 230u : 40u + 50u * std::uint32_t(x), g = light ? 200u : 90u, b = light ? 120u : 60u + 40u * std::uint32_t(y);
    return r | g << 8 | b << 16 | 255u << 24;
}

std::string Check::summary() const {
    std::ostringstream s;
    s << checked << " pixels checked, " << skipped << " on edges skipped, " << mismatched << " differ";
    if (!firstMismatch.empty()) s << " (first: " << firstMismatch << ")";
    if (checked == 0) s << "; nothing was checked";
    return s.str();
}

Check checkFrame(const std::vector<std::uint8_t>& rgba, int width, int height, double seconds, const float meshColor[4]) {
    const double clear[4] = {0.0, 0.125, 0.3, 1.0};
    Check out;
    int cubePixels = 0;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const Hit centre = trace(x + 0.5, y + 0.5, width, height, seconds, meshColor);
            bool edge = false;
            for (double dx : {-0.45, 0.45})
                for (double dy : {-0.45, 0.45}) edge |= !trace(x + 0.5 + dx, y + 0.5 + dy, width, height, seconds, meshColor).sameAs(centre);
            if (edge) {
                ++out.skipped;
                continue;
            }
            ++out.checked;
            if (centre.face >= 0) ++cubePixels;
            for (int c = 0; c < 4; ++c) {
                const double expected = (centre.face >= 0 ? centre.rgba[c] : clear[c]) * 255;
                const double got = rgba[std::size_t((y * width + x) * 4 + c)];
                if (std::abs(got - expected) > 3) {
                    if (out.mismatched++ == 0) {
                        std::ostringstream m;
                        m << "pixel (" << x << ", " << y << ") channel " << c << " is " << got << ", expected " << expected;
                        out.firstMismatch = m.str();
                    }
                    break;
                }
            }
        }
    if (cubePixels == 0) out.checked = 0;  // a frame without the cube proves nothing
    return out;
}

}  // namespace cube
