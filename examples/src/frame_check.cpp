// FrameCheck: see frame_check.h. The numbers mirror cube_game.cpp and the effects; the method is
// independent: a ray per pixel against the cube's six planes instead of triangles and a depth buffer.
#include "frame_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "check_math.h"

#include "cube_game.h"

namespace example {

namespace {

constexpr int kTolerance = 2;  // 8-bit steps: three quantisations (scene, graded, back buffer)

struct Hit {
    int face = -1;  // -1: background; else axis * 2 + (positive side ? 1 : 0)
    Vec3 modelNormal{};
};

// The ray through D3D NDC (x, y) from the camera, in model space, against the cube [-0.5, 0.5]^3.
Hit castRay(double ndcX, double ndcY, const Mat3& modelToWorld, double aspect) {
    const double yScale = 1.0 / std::tan(double(SceneSettings::FieldOfView) / 2.0), xScale = yScale / aspect;
    // CreateLookAt from (0, 0, D) at the origin with +Y up: view axes are the world axes.
    Vec3 origin{0, 0, double(SceneSettings::CameraDistance)};
    Vec3 direction{ndcX / xScale, ndcY / yScale, -1};
    Mat3 worldToModel = transposed(modelToWorld);  // a rotation
    origin = times(origin, worldToModel);
    direction = times(direction, worldToModel);
    double tNear = -1e30, tFar = 1e30;
    int nearAxis = -1;
    for (int axis = 0; axis < 3; ++axis) {
        if (std::abs(direction[axis]) < 1e-300) {
            if (std::abs(origin[axis]) > 0.5) return {};
            continue;
        }
        double t0 = (-0.5 - origin[axis]) / direction[axis], t1 = (0.5 - origin[axis]) / direction[axis];
        if (t0 > t1) std::swap(t0, t1);
        if (t0 > tNear) tNear = t0, nearAxis = axis;
        tFar = std::min(tFar, t1);
    }
    if (tNear > tFar || tNear <= 0 || nearAxis < 0) return {};
    Hit hit;
    bool positive = origin[nearAxis] + tNear * direction[nearAxis] > 0;
    hit.face = nearAxis * 2 + (positive ? 1 : 0);
    hit.modelNormal[std::size_t(nearAxis)] = positive ? 1 : -1;
    return hit;
}

double byte(double v) { return std::round(std::clamp(v, 0.0, 1.0) * 255.0); }

}  // namespace

bool FrameCheck::passed() const {
    // The cube and the background must both be there, and at least 90 % of the frame away from
    // edges, or the check would check little.
    return mismatches == 0 && notOpaque == 0 && cubePixels > 0 && backgroundPixels > 0 && compared * 10 >= total * 9;
}

std::string FrameCheck::summary() const {
    std::ostringstream s;
    s << compared << " of " << total << " pixels compared (" << cubePixels << " cube, " << backgroundPixels << " background), max difference "
      << maxDifference << "/255 (tolerance " << kTolerance << "), " << mismatches << " mismatches, " << notOpaque
      << " pixels not opaque: " << (passed() ? "ok" : "FAILED");
    return s.str();
}

FrameCheck checkFrame(const std::vector<fxport::Color>& pixels, int width, int height, double totalSeconds) {
    FrameCheck result;
    const double aspect = double(width) / double(height);
    const Mat3 modelToWorld = times(rotationY(double(SceneSettings::AngleAt(totalSeconds))), rotationX(double(SceneSettings::Tilt)));
    // BasicEffect lit by CubeGame's light (XNA's equation: DiffuseColor * (ambient + sum of
    // max(N.L, 0) * light diffuse), no emissive, no specular), the glTF material's base colour,
    // Grading.fxh's and Scanlines.fx's defaults.
    const Vec3 light{-0.5, -0.7, -0.5};
    const double lightLength = std::sqrt(dot(light, light));
    const Vec3 toLight{-light[0] / lightLength, -light[1] / lightLength, -light[2] / lightLength};
    const Vec3 baseColor{0.9, 0.55, 0.2};
    const double ambient = SceneSettings::Ambient, lightDiffuse = SceneSettings::LightDiffuse;
    const double desaturation = 0.3, vignette = 0.8, scanlineStrength = 0.15;
    const Vec3 cornflowerBlue{100, 149, 237};

    for (int py = 0; py < height; ++py)
        for (int px = 0; px < width; ++px) {
            const fxport::Color& got = pixels[std::size_t(py) * std::size_t(width) + std::size_t(px)];
            if (got.A != 255) ++result.notOpaque;
            // vs_3_0 (D3D9): pixel (px, py) samples the scene at integer screen coordinates.
            auto ndcX = [&](double x) { return 2.0 * x / width - 1.0; };
            auto ndcY = [&](double y) { return 1.0 - 2.0 * y / height; };
            Hit hit = castRay(ndcX(px), ndcY(py), modelToWorld, aspect);
            bool interior = true;  // the same face (or none) 0.6 pixel around: not on an edge
            for (double dx : {-0.6, 0.6})
                for (double dy : {-0.6, 0.6}) interior = interior && castRay(ndcX(px + dx), ndcY(py + dy), modelToWorld, aspect).face == hit.face;
            if (!interior) continue;

            Vec3 scene;  // the scene target, 8-bit
            if (hit.face < 0) {
                scene = cornflowerBlue;
                ++result.backgroundPixels;
            } else {
                Vec3 normal = times(hit.modelNormal, modelToWorld);
                double lambert = ambient + lightDiffuse * std::max(dot(normal, toLight), 0.0);
                for (int c = 0; c < 3; ++c) scene[std::size_t(c)] = byte(baseColor[std::size_t(c)] * lambert);
                ++result.cubePixels;
            }
            // PostProcess.fx on the 8-bit scene into the 8-bit graded target, then Scanlines.fx;
            // SpriteBatch gives pixel (px, py) the texel's centre.
            Vec3 s{scene[0] / 255, scene[1] / 255, scene[2] / 255};
            double grey = dot(s, Vec3{0.299, 0.587, 0.114});
            double u = (px + 0.5) / width - 0.5, v = (py + 0.5) / height - 0.5;
            double darken = std::clamp(1 - vignette * 2 * (u * u + v * v), 0.0, 1.0);
            double scanline = 1 - scanlineStrength * (py % 2);
            const int got3[3] = {got.R, got.G, got.B};
            ++result.compared;
            bool mismatch = false;
            for (int c = 0; c < 3; ++c) {
                double graded = byte((s[std::size_t(c)] + (grey - s[std::size_t(c)]) * desaturation) * darken);
                double expected = byte(graded / 255 * scanline);
                int difference = std::abs(got3[c] - int(expected));
                result.maxDifference = std::max(result.maxDifference, difference);
                mismatch = mismatch || difference > kTolerance;
            }
            result.mismatches += mismatch;
        }
    result.total = width * height;
    return result;
}

}  // namespace example
