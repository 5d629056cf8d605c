// lighting2d's unwrap (Unwrap.fx, UnwrapSpotlight.fx) on rays with sin(theta) or cos(theta)
// exactly 0, the texels of those rays against the same formula in double.
//
// The effects divide by sin(theta) and cos(theta) to find where a ray leaves the caster texture and
// guard the exact zeros with their own branches (cos == 0: the horizontal distances; sin == 0: the
// vertical). The rays are forced exactly: Unwrap.fx gets a zero-width source rectangle, so
// texCoord.x is one constant (0: theta = 0; 0.5: theta = float(pi/2); 1: theta = float(pi));
// UnwrapSpotlight.fx gets MinAngle = MaxAngle = theta. Only theta = 0 reaches a guard: no float
// angle has cos exactly 0 or a non-zero one sin exactly 0 (cos(float(pi/2)) = -4.4e-8,
// sin(float(pi)) = -8.7e-8), so those rays take the general branch, whose divisions give 1e7-size
// exits that the min() discards -- the same distances as the guard would. The caster texture is
// opaque everywhere, so every texel is LightDist * texCoord.y / DiagonalLength (no sampling edge).
#include <cmath>
#include <cstdio>

#include "stability/case_support.h"

namespace fxport::stability {

namespace {

constexpr int kTW = 64, kTH = 48;
constexpr float kPI = 3.14159265f;  // the effects' #define PI, as a float
const double kDiagonal = std::sqrt(double(kTW) * kTW + double(kTH) * kTH);
// texCoord.y at row y of the destination: XNA's SpriteBatch -0.5 pixel and the runtime's D3D9
// pixel-centre emulation (demo/lighting2d/reference_check.cpp).
constexpr double kRowBias = 0.5 + 1.0 / 256;

struct UnwrapCase {
    std::string name;
    bool spot;
    float value;  // point: texCoord.x; spot: theta
    double lx, ly;
};

// The distances the effect computes for a ray at float angle theta (Unwrap.fx: .x right ray, .y left);
// `exactRay`: for the exact angle the case stands for (sin, cos within 1e-6 of 0 taken as 0).
void unwrapDistances(const UnwrapCase& c, double out[2], bool exactRay = false) {
    const float theta = c.spot ? c.value : c.value * kPI;
    double sn = std::sin(double(theta)), cs = std::cos(double(theta));
    if (exactRay) sn = std::fabs(sn) < 1e-6 ? 0 : sn, cs = std::fabs(cs) < 1e-6 ? 0 : cs;
    const double TW = kTW, TH = kTH, Lx = c.lx, Ly = c.ly;
    auto neg = [&](double h) { return h < 0 ? 2 * TW : h; };
    if (!c.spot) {
        if (cs == 0) out[0] = TW - Lx, out[1] = Lx;
        else if (sn == 0) out[0] = out[1] = std::fabs(((cs + 1) / 2.0) * TH - Ly);
        else {
            const double hx = neg(-Ly / cs), hy = neg(Lx / sn), hz = neg((TH - Ly) / cs), hw = neg((TW - Lx) / sn);
            out[0] = std::min(hw, std::min(hx, hz)), out[1] = std::min(hy, std::min(hx, hz));
        }
    } else {
        if (cs == 0) out[0] = std::fabs(((sn + 1) / 2.0) * TW - Lx);
        else if (sn == 0) out[0] = std::fabs(((cs + 1) / 2.0) * TH - Ly);
        else {
            const double hx = neg(-Ly / cs), hy = neg(-Lx / sn), hz = neg((TH - Ly) / cs), hw = neg((TW - Lx) / sn);
            out[0] = std::min(std::min(hx, hz), std::min(hy, hw));
        }
        out[1] = 0;
    }
}

CaseResult runUnwrap(GraphicsDevice& device, SpriteBatch& batch, Effect& effect, Texture2D& casters, const UnwrapCase& c,
                     int n) {
    CaseResult r;
    r.group = "unwrap";
    r.name = c.name;
    r.variant = "as written";
    r.relative = false;
    RenderTarget2D target(device, n, n, false, SurfaceFormat::Vector4, DepthFormat::None);
    target.Name = "unwrapTarget (Vector4)";
    effect.Parameters["LightPos"].SetValue(Vector2(float(c.lx), float(c.ly)));
    effect.Parameters["TextureWidth"].SetValue(float(kTW));
    effect.Parameters["TextureHeight"].SetValue(float(kTH));
    effect.Parameters["DiagonalLength"].SetValue(float(kDiagonal));
    if (c.spot) {
        effect.Parameters["MinAngle"].SetValue(c.value);
        effect.Parameters["MaxAngle"].SetValue(c.value);
    }
    FiniteCheck check(device);
    check.beginPass(c.spot ? "UnwrapSpotlight" : "Unwrap");
    device.SetRenderTarget(target);
    device.Clear(Color::Transparent);
    batch.Begin(SpriteSortMode::Deferred, BlendState::Opaque, SamplerState::PointClamp, nullptr, nullptr, effect);
    if (c.spot) {
        batch.Draw(casters, Rectangle(0, 0, n, n), Color::White);
    } else {
        // A zero-width source rectangle at x = value * TW: texCoord.x = value on every pixel.
        const Rectangle source(int(c.value * kTW), 0, 0, kTH);
        batch.Draw(casters, Rectangle(0, 0, n, n), source, Color::White);
    }
    batch.End();
    device.SetRenderTarget(nullptr);
    takeFindings(check.endPass(), r);

    double distance[2], exact[2];
    unwrapDistances(c, distance);
    unwrapDistances(c, exact, true);
    const std::vector<Vector4> texels = target.GetDataAsVector4();
    Accumulator acc;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const Vector4 t = texels[std::size_t(y) * std::size_t(n) + std::size_t(x)];
            if (!(std::isfinite(t.X) && std::isfinite(t.Y))) continue;
            const double v = (y + kRowBias) / n;
            const double e = std::fmax(std::fabs(t.X - distance[0] * v / kDiagonal),
                                       c.spot ? std::fabs(double(t.Y)) : std::fabs(t.Y - distance[1] * v / kDiagonal));
            acc.add(e);
        }
    acc.into(r);
    const float theta = c.spot ? c.value : c.value * kPI;
    char note[384];
    std::snprintf(note, sizeof note,
                  "light (%g, %g) in %dx%d casters; theta = %.9g: sin %.3g, cos %.3g (%s branch); LightDist %s = (%g, %g), "
                  "the exact ray's (guarded branch) (%g, %g); error = max |texel - LightDist v / diagonal|",
                  c.lx, c.ly, kTW, kTH, double(theta), std::sin(double(theta)), std::cos(double(theta)),
                  std::sin(double(theta)) == 0 ? "sin == 0" : std::cos(double(theta)) == 0 ? "cos == 0" : "general",
                  c.spot ? "(ray)" : "(right, left)", distance[0], distance[1], exact[0], exact[1]);
    r.note = note;
    return r;
}

}  // namespace

void runUnwrapCases(GraphicsDevice& device, const SuiteOptions& options, std::vector<CaseResult>& results) {
    const std::string fx = options.hlslDir + "/lighting2d/";
    Effect unwrap(device, fx + "Unwrap.fx");
    Effect unwrapSpot(device, fx + "UnwrapSpotlight.fx");
    SpriteBatch batch(device);
    Texture2D casters(device, kTW, kTH, false, SurfaceFormat::Color);
    casters.SetData(std::vector<Color>(std::size_t(kTW) * kTH, Color::White));
    const double pi2 = double(kPI / 2);
    const UnwrapCase cases[] = {
        {"point u=0 (sin 0)", false, 0.0f, 20.5, 13.25},
        {"point u=0 (sin 0), light x=0", false, 0.0f, 0, 13.25},
        {"point u=0.5 (cos~0)", false, 0.5f, 20.5, 13.25},
        {"point u=0.5 (cos~0), light y=0", false, 0.5f, 20.5, 0},
        {"point u=1 (sin~0)", false, 1.0f, 20.5, 13.25},
        {"point u=1 (sin~0), light x=0", false, 1.0f, 0, 13.25},
        {"spot 0 (sin 0)", true, 0.0f, 20.5, 13.25},
        {"spot 0 (sin 0), light x=0", true, 0.0f, 0, 13.25},
        {"spot pi/2 (cos~0)", true, float(pi2), 20.5, 13.25},
        {"spot -pi/2 (cos~0)", true, -float(pi2), 20.5, 13.25},
        {"spot pi (sin~0)", true, kPI, 20.5, 13.25},
        {"spot pi (sin~0), light x=0", true, kPI, 0, 13.25},
    };
    for (const UnwrapCase& c : cases)
        results.push_back(runUnwrap(device, batch, c.spot ? unwrapSpot : unwrap, casters, c, options.size));
}

}  // namespace fxport::stability
