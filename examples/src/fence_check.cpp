// checkFenceFrame: see fence_check.h. The numbers mirror fence_game.cpp, Fence.fx and Cube.gltf; the
// method is independent of the GPU's: rays against planes instead of triangles and a depth buffer,
// XNA's lighting equations and rig written out here in double precision.
#include "fence_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "check_math.h"

#include "fence_game.h"

namespace example {

namespace {

// 8-bit steps. Lit pixels: per-pixel lighting with a power-16 highlight in float on the GPU.
// Flat ones: one quantisation of a texel times the tint, or the clear colour.
constexpr int kLitTolerance = 3;
constexpr int kFlatTolerance = 1;
constexpr int kInkTolerance = 2;  // a text pixel's distance from the sky-to-white line

Vec3 add(const Vec3& a, const Vec3& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Vec3 scaled(const Vec3& a, double s) { return {a[0] * s, a[1] * s, a[2] * s}; }
Vec3 normalized(const Vec3& a) { return scaled(a, 1.0 / std::sqrt(dot(a, a))); }

double byte(double v) { return std::round(std::clamp(v, 0.0, 1.0) * 255.0); }

// XNA's EnableDefaultLighting (its documented key, fill and back lights and ambient colour).
struct Light {
    Vec3 direction, diffuse, specular;
};
const Light kRig[3] = {
    {{-0.5265408, -0.5735765, -0.6275069}, {1.0, 0.9607844, 0.8078432}, {1.0, 0.9607844, 0.8078432}},
    {{0.7198464, 0.3420201, 0.6040227}, {0.9647059, 0.7607844, 0.4078432}, {0, 0, 0}},
    {{0.4545195, -0.7660444, 0.4545195}, {0.3231373, 0.3607844, 0.3937255}, {0.3231373, 0.3607844, 0.3937255}},
};
const Vec3 kAmbient{0.05333332, 0.09882354, 0.1819608};
const Vec3 kCrateDiffuse{0.9, 0.55, 0.2};  // Cube.gltf's baseColorFactor; BasicEffect's
constexpr double kSpecularPower = 16;      // default SpecularColor (white) and SpecularPower
constexpr int kAlphaRef = 128;             // Fence.fx: AlphaFunc = Greater; AlphaRef = 128;
const Vec3 kSky{100, 149, 237};            // Color.CornflowerBlue

// What one point of the screen shows. `region` is equal for points that show the same thing (the
// same fence texel, crate face or sky), so a pixel whose neighbourhood is one region is not an edge.
struct Expected {
    int region = 0;
    Vec3 rgb{};  // 0..255, rounded as an 8-bit target stores it
    bool lit = false;
    bool gate = false;  // on the gate (AlphaTestEffect) rather than the fence (Fence.fx)
    enum class What { Sky, Crate, Board, Knot, HoleSky, HoleCrate, Knothole } what = What::Sky;
};

class Scene {
public:
    explicit Scene(const FenceFrame& f) : f_(f) {
        const double aspect = double(f.width) / double(f.height);
        yScale_ = 1.0 / std::tan(double(FenceScene::FieldOfView) / 2.0);
        xScale_ = yScale_ / aspect;
        modelToWorld_ = times(rotationY(double(FenceScene::CrateAngleAt(f.totalSeconds))), rotationX(double(FenceScene::CrateTilt)));
        const fxport::Vector3 tint = FenceScene::FenceTint();
        tint_ = {tint.X, tint.Y, tint.Z};
    }

    // (x, y): a point in pixels from the top-left corner. Fence.fx and BasicEffect are vs_2_0/vs_3_0
    // (D3D9): pixel (px, py) shows the scene at the screen point (px, py) itself.
    Expected at(double x, double y) const {
        const double ndcX = 2.0 * x / f_.width - 1.0, ndcY = 1.0 - 2.0 * y / f_.height;
        // CreateLookAt from (0, 0, D) at the origin with +Y up: the view axes are the world axes.
        const Vec3 eye{0, 0, double(FenceScene::CameraDistance)};
        const Vec3 direction{ndcX / xScale_, ndcY / yScale_, -1};

        Expected e;
        // The fence (Fence.fx, tinted) and the gate (AlphaTestEffect, white): quads at z = FenceZ,
        // point-sampled, kept where the texel's alpha is above AlphaRef.
        struct Panel {
            double left, right, bottom, top;
            Vec3 tint;
        };
        const Panel panels[2] = {
            {FenceScene::FenceLeft, FenceScene::FenceRight, FenceScene::FenceBottom, FenceScene::FenceTop, tint_},
            {FenceScene::GateLeft, FenceScene::GateRight, FenceScene::GateBottom, FenceScene::GateTop, {1, 1, 1}},
        };
        int texel = -1, panel = -1;
        const double t = double(FenceScene::CameraDistance) - double(FenceScene::FenceZ);
        const double px = direction[0] * t, py = direction[1] * t;
        for (int i = 0; i < 2 && texel < 0; ++i) {
            const Panel& p = panels[i];
            if (px < p.left || px > p.right || py < p.bottom || py > p.top) continue;
            const double u = (px - p.left) / (p.right - p.left), v = (p.top - py) / (p.top - p.bottom);
            const int tx = std::clamp(int(std::floor(u * f_.fenceWidth)), 0, f_.fenceWidth - 1);
            const int ty = std::clamp(int(std::floor(v * f_.fenceHeight)), 0, f_.fenceHeight - 1);
            texel = ty * f_.fenceWidth + tx;
            panel = i;
            const fxport::Color& c = (*f_.fenceTexels)[std::size_t(texel)];
            if (c.A > kAlphaRef) {
                e.region = 1000 * (i + 1) + texel;
                e.what = c.A == 255 ? Expected::What::Board : Expected::What::Knot;
                e.gate = i == 1;
                e.rgb = {byte(c.R / 255.0 * p.tint[0]), byte(c.G / 255.0 * p.tint[1]), byte(c.B / 255.0 * p.tint[2])};
                return e;
            }
        }
        const int face = crateFace(eye, direction, e.rgb);
        e.lit = face >= 0;
        e.gate = panel == 1;
        if (face < 0) e.rgb = kSky;
        e.region = ((panel + 1) * 100 + texel + 1) * 8 + face + 1;
        if (texel < 0) e.what = face < 0 ? Expected::What::Sky : Expected::What::Crate;
        else if ((*f_.fenceTexels)[std::size_t(texel)].A > 0) e.what = Expected::What::Knothole;
        else e.what = face < 0 ? Expected::What::HoleSky : Expected::What::HoleCrate;
        return e;
    }

private:
    // The crate [-0.5, 0.5]^3 turned by the world matrix: the face the ray meets first (-1: none)
    // and its colour, lit by BasicEffect per pixel:
    //   rgb = DiffuseColor * (ambient + sum max(N.L, 0) * light diffuse)
    //       + sum pow(max(N.H, 0), SpecularPower) * light specular  (where N.L >= 0; H = normalize(toEye + L))
    int crateFace(const Vec3& eye, const Vec3& direction, Vec3& rgb) const {
        const Mat3 worldToModel = transposed(modelToWorld_);  // a rotation
        const Vec3 origin = times(eye, worldToModel), dir = times(direction, worldToModel);
        double tNear = -1e30, tFar = 1e30;
        int nearAxis = -1;
        for (int axis = 0; axis < 3; ++axis) {
            if (std::abs(dir[axis]) < 1e-300) {
                if (std::abs(origin[axis]) > 0.5) return -1;
                continue;
            }
            double t0 = (-0.5 - origin[axis]) / dir[axis], t1 = (0.5 - origin[axis]) / dir[axis];
            if (t0 > t1) std::swap(t0, t1);
            if (t0 > tNear) tNear = t0, nearAxis = axis;
            tFar = std::min(tFar, t1);
        }
        if (tNear > tFar || tNear <= 0 || nearAxis < 0) return -1;
        const bool positive = origin[nearAxis] + tNear * dir[nearAxis] > 0;
        Vec3 modelNormal{};
        modelNormal[std::size_t(nearAxis)] = positive ? 1 : -1;
        const Vec3 normal = times(modelNormal, modelToWorld_);
        const Vec3 position = add(eye, scaled(direction, tNear));
        const Vec3 toEye = normalized(add(eye, scaled(position, -1)));
        Vec3 diffuse{}, specular{};
        for (const Light& light : kRig) {
            const Vec3 toLight = scaled(light.direction, -1);
            const double nDotL = dot(normal, toLight);
            const double reaches = nDotL >= 0 ? 1 : 0;
            const double nDotH = dot(normal, normalized(add(toEye, toLight)));
            const double highlight = std::pow(std::max(nDotH, 0.0) * reaches, kSpecularPower);
            for (std::size_t c = 0; c < 3; ++c) {
                diffuse[c] += light.diffuse[c] * reaches * nDotL;
                specular[c] += light.specular[c] * highlight;
            }
        }
        for (std::size_t c = 0; c < 3; ++c) rgb[c] = byte(diffuse[c] * kCrateDiffuse[c] + kAmbient[c] * kCrateDiffuse[c] + specular[c]);
        return nearAxis * 2 + (positive ? 1 : 0);
    }

    const FenceFrame& f_;
    double xScale_ = 1, yScale_ = 1;
    Mat3 modelToWorld_{};
    Vec3 tint_{};
};

}  // namespace

std::string FenceFrameCheck::summary() const {
    std::ostringstream s;
    s << compared << " of " << total << " pixels compared: crate " << crate << ", sky " << sky << "; fence boards " << boards
      << ", knots " << knots << " (kept), holes " << holesShowingSky << " to the sky and " << holesShowingCrate
      << " to the crate, knotholes " << knotholes << " (discarded); of these on the gate " << gateKept << " kept, "
      << gateDiscarded << " discarded; max difference lit " << maxLitDifference << "/255 (tolerance "
      << kLitTolerance << "), flat " << maxFlatDifference << "/255 (tolerance " << kFlatTolerance << "), " << mismatches
      << " mismatches; text box " << textBoxPixels << " pixels, " << inkPixels << " ink, " << inkOffBlendLine
      << " off the blend line, ink x " << inkLeft << ".." << inkRight << " y " << inkTop << ".." << inkBottom << ": "
      << (passed() ? "ok" : "FAILED\n" + problems);
    return s.str();
}

FenceFrameCheck checkFenceFrame(const FenceFrame& f) {
    FenceFrameCheck r;
    r.total = f.width * f.height;
    const Scene scene(f);
    // The text box, whole pixels: a pixel is in it when it overlaps MeasureString's rectangle.
    const int boxLeft = int(std::floor(f.textPosition.X)), boxTop = int(std::floor(f.textPosition.Y));
    const int boxRight = int(std::ceil(f.textPosition.X + f.textSize.X)), boxBottom = int(std::ceil(f.textPosition.Y + f.textSize.Y));
    std::vector<int> inkInColumn(std::size_t(f.width), 0);

    for (int py = 0; py < f.height; ++py)
        for (int px = 0; px < f.width; ++px) {
            const fxport::Color& got = (*f.pixels)[std::size_t(py) * std::size_t(f.width) + std::size_t(px)];
            if (got.A != 255) ++r.notOpaque;
            const Expected e = scene.at(px, py);
            bool interior = true;  // the same region 0.6 pixel around: not on an edge
            for (double dx : {-0.6, 0.6})
                for (double dy : {-0.6, 0.6}) interior = interior && scene.at(px + dx, py + dy).region == e.region;
            const double gotRgb[3] = {double(got.R), double(got.G), double(got.B)};

            if (px >= boxLeft && px < boxRight && py >= boxTop && py < boxBottom) {
                // Premultiplied white text over the scene: got = c * 255 + (1 - c) * scene, one c for
                // all three channels; c from the channel with the most room below white.
                ++r.textBoxPixels;
                if (!interior) continue;
                std::size_t k = 0;
                for (std::size_t c = 1; c < 3; ++c)
                    if (e.rgb[c] < e.rgb[k]) k = c;
                const double room = 255 - e.rgb[k];
                const double coverage = room > 0 ? (gotRgb[k] - e.rgb[k]) / room : 0;
                bool onLine = coverage > -kInkTolerance / std::max(room, 1.0) && coverage < 1 + kInkTolerance / std::max(room, 1.0);
                for (std::size_t c = 0; c < 3; ++c)
                    onLine = onLine && std::abs(gotRgb[c] - (coverage * 255 + (1 - coverage) * e.rgb[c])) <= kInkTolerance;
                if (!onLine) ++r.inkOffBlendLine;
                if (coverage > 0.5) {
                    ++r.inkPixels;
                    ++inkInColumn[std::size_t(px)];
                    r.inkLeft = std::min(r.inkLeft, px), r.inkRight = std::max(r.inkRight, px);
                    r.inkTop = std::min(r.inkTop, py), r.inkBottom = std::max(r.inkBottom, py);
                }
                continue;
            }
            if (!interior) continue;
            ++r.compared;
            int difference = 0;
            for (std::size_t c = 0; c < 3; ++c) difference = std::max(difference, int(std::abs(gotRgb[c] - e.rgb[c])));
            if (e.lit) r.maxLitDifference = std::max(r.maxLitDifference, difference);
            else r.maxFlatDifference = std::max(r.maxFlatDifference, difference);
            r.mismatches += difference > (e.lit ? kLitTolerance : kFlatTolerance);
            if (e.gate) {
                const bool kept = e.what == Expected::What::Board || e.what == Expected::What::Knot;
                ++(kept ? r.gateKept : r.gateDiscarded);
            }
            switch (e.what) {
            case Expected::What::Sky: ++r.sky; break;
            case Expected::What::Crate: ++r.crate; break;
            case Expected::What::Board: ++r.boards; break;
            case Expected::What::Knot: ++r.knots; break;
            case Expected::What::HoleSky: ++r.holesShowingSky; break;
            case Expected::What::HoleCrate: ++r.holesShowingCrate; break;
            case Expected::What::Knothole: ++r.knotholes; break;
            }
        }

    // Each printed character has ink between the pen positions MeasureString gives around it (a
    // pixel of slack: antialiasing and glyph bearings).
    for (const auto& [before, after] : f.characterAdvances) {
        if (after <= before) continue;  // a space
        const int from = std::max(0, int(std::floor(f.textPosition.X + before)) - 1);
        const int to = std::min(f.width, int(std::ceil(f.textPosition.X + after)) + 1);
        int ink = 0;
        for (int x = from; x < to; ++x) ink += inkInColumn[std::size_t(x)];
        r.charactersWithoutInk += ink == 0;
    }

    std::ostringstream problems;
    auto require = [&](bool ok, const std::string& what) {
        if (!ok) problems << "  " << what << "\n";
    };
    require(r.mismatches == 0, std::to_string(r.mismatches) + " pixels differ from the CPU computation");
    require(r.notOpaque == 0, std::to_string(r.notOpaque) + " pixels are not opaque");
    require(r.compared * 10 >= (r.total - r.textBoxPixels) * 8, "fewer than 80 % of the pixels outside the text were compared");
    require(r.crate > 0 && r.sky > 0, "the crate or the sky is missing");
    require(r.boards > 0 && r.knots > 0, "no fence texel with alpha 255 or with alpha in 129..254 was seen kept");
    require(r.holesShowingSky > 0 && r.holesShowingCrate > 0, "no hole of the fence (alpha 0) was seen over the sky and over the crate");
    require(r.knotholes > 0, "no knothole (alpha in 1..128, below AlphaRef) was seen discarded");
    require(r.gateKept > 0 && r.gateDiscarded > 0, "the gate (AlphaTestEffect) showed no kept or no discarded texel");
    require(r.inkOffBlendLine == 0, std::to_string(r.inkOffBlendLine) + " text-box pixels are not white blended over the scene");
    require(r.inkPixels * 20 >= r.textBoxPixels && r.inkPixels * 2 <= r.textBoxPixels,
            "the text box is not 5..50 % ink (" + std::to_string(r.inkPixels) + " of " + std::to_string(r.textBoxPixels) + ")");
    require(r.inkLeft <= boxLeft + 3 && r.inkRight >= boxRight - 4, "the ink does not span MeasureString's width");
    require(r.inkBottom - r.inkTop + 1 >= (boxBottom - boxTop) * 2 / 5, "the ink is less than 2/5 of MeasureString's height");
    require(r.charactersWithoutInk == 0, std::to_string(r.charactersWithoutInk) + " characters have no ink between their pen positions");
    r.problems = problems.str();
    return r;
}

}  // namespace example
