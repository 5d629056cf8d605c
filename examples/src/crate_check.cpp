// The crate game's CPU check: see crate_check.h.
#include "crate_check.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>

#include "check_math.h"
#include "crate_game.h"

namespace example {

namespace {

// Crate.dds, 8x8 in four 4x4 DXT1 blocks of one colour each, as seen on every face (u right, v down).
fxport::Color blockColour(double u, double v) {
    const fxport::Color colours[4] = {fxport::Color(255, 0, 0, 255), fxport::Color(0, 255, 0, 255), fxport::Color(0, 0, 255, 255),
                                      fxport::Color(255, 255, 255, 255)};
    return colours[(v < 0.5 ? 0 : 2) + (u < 0.5 ? 0 : 1)];
}

struct Hit {
    Vec3 point;  // object space
    int axis;    // the face entered: axis and sign of its outward normal
    double sign;
};

// Ray against the cube [-h, h]^3 (slabs); the entry face.
std::optional<Hit> castRay(const Vec3& origin, const Vec3& dir, double h) {
    double tNear = -1e30, tFar = 1e30;
    int axis = 0;
    for (int k = 0; k < 3; ++k) {
        if (std::abs(dir[k]) < 1e-12) {
            if (std::abs(origin[k]) > h) return std::nullopt;
            continue;
        }
        double t0 = (-h - origin[k]) / dir[k], t1 = (h - origin[k]) / dir[k];
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > tNear) tNear = t0, axis = k;
        tFar = std::min(tFar, t1);
    }
    if (tNear > tFar || tNear < 0) return std::nullopt;
    Hit hit{{origin[0] + tNear * dir[0], origin[1] + tNear * dir[1], origin[2] + tNear * dir[2]}, axis, 0};
    hit.sign = hit.point[axis] > 0 ? 1 : -1;
    return hit;
}

Vec3 cross(const Vec3& a, const Vec3& b) { return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]}; }

// The texture coordinate Crate.x gives a point of a face. The file is left-handed: its z is the
// model's -z (the importer mirrors z). Each face's corners there are centre + (-right + up) / 2 ...
// with up = +y on the sides, +z on top, -z below, and right = cross(up, -normal) (see Crate.x).
std::pair<double, double> faceUv(const Hit& hit) {
    Vec3 p = {hit.point[0], hit.point[1], -hit.point[2]};
    Vec3 n = {0, 0, 0};
    n[hit.axis] = hit.axis == 2 ? -hit.sign : hit.sign;
    const Vec3 up = hit.axis != 1 ? Vec3{0, 1, 0} : Vec3{0, 0, n[1]};
    const Vec3 right = cross(up, {-n[0], -n[1], -n[2]});
    const Vec3 fromCentre = {p[0] - 0.5 * n[0], p[1] - 0.5 * n[1], p[2] - 0.5 * n[2]};
    return {dot(fromCentre, right) + 0.5, 0.5 - dot(fromCentre, up)};
}

}  // namespace

std::string CrateCheck::summary() const {
    std::ostringstream out;
    out << compared << " pixels compared (" << cratePixels << " on the crate, " << colours << " of 4 block colours seen), "
        << mismatches << " differ by more than 2/255, largest difference " << maxDifference << ": " << (passed() ? "ok" : "FAILED");
    return out.str();
}

CrateCheck checkCrateFrame(const std::vector<fxport::Color>& pixels, int width, int height) {
    CrateCheck check;
    // world = RotationY(turn) * RotationX(tilt); a world point w is object point w * transpose(world).
    const Mat3 toObject = transposed(times(rotationY(CrateScene::Turn), rotationX(CrateScene::Tilt)));
    const double tanHalf = std::tan(double(CrateScene::FieldOfView) / 2), aspect = double(width) / double(height);
    const Vec3 eye = times(Vec3{0, 0, double(CrateScene::CameraDistance)}, toObject);
    bool seen[4] = {false, false, false, false};
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const double ndcX = (x + 0.5) / width * 2 - 1, ndcY = 1 - (y + 0.5) / height * 2;
            const Vec3 dir = times(Vec3{ndcX * tanHalf * aspect, ndcY * tanHalf, -1}, toObject);
            // Near the silhouette the answer depends on rasterisation: skip where a slightly
            // smaller and a slightly larger crate disagree.
            const auto hit = castRay(eye, dir, 0.5), inner = castRay(eye, dir, 0.47), outer = castRay(eye, dir, 0.53);
            if (inner.has_value() != outer.has_value()) continue;
            fxport::Color expected = fxport::Color::CornflowerBlue;
            if (hit) {
                const auto [u, v] = faceUv(*hit);
                const double margin = 0.06;  // block borders and face edges
                if (std::abs(u - 0.5) < margin || std::abs(v - 0.5) < margin || u < margin || v < margin || u > 1 - margin || v > 1 - margin)
                    continue;
                if (inner->axis != hit->axis || outer->axis != hit->axis) continue;
                expected = blockColour(u, v);
                seen[(v < 0.5 ? 0 : 2) + (u < 0.5 ? 0 : 1)] = true;
                ++check.cratePixels;
            }
            const fxport::Color& got = pixels[std::size_t(y) * std::size_t(width) + std::size_t(x)];
            const int difference = std::max({std::abs(got.R - expected.R), std::abs(got.G - expected.G), std::abs(got.B - expected.B)});
            check.maxDifference = std::max(check.maxDifference, difference);
            if (difference > 2) ++check.mismatches;
            ++check.compared;
        }
    check.colours = int(std::count(seen, seen + 4, true));
    return check;
}

}  // namespace example
