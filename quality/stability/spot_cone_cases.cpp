// Spot cone angles near 0 and 180 degrees through xna-deferred SpotLight.fx.
//
// The effect lights a pixel when SL = dot(L, S) <= LightAngleCos, L the unit vector from the pixel
// to the light, S the spot direction, and the demo sets LightAngleCos = cos(FOV), FOV the full cone
// angle of the light's projection (the cookie's frustum). Since L points back at the light, the test
// admits angle(-L, S) <= 180 - FOV: at the seed's FOV = 90 degrees that is the half space in front of
// the light, and the cookie (projected with FOV) cuts the cone. Away from 90 the test is wrong: for
// FOV < 90 it admits pixels behind the light, where the cookie's projection (w < 0) is mirrored;
// for FOV > 120 it is narrower than the cone (FOV -> 180: only the axis). Fix (host, opt-in, no edit
// of the effect): set LightAngleCos = -cos(FOV / 2), which makes the test angle(-L, S) <= FOV / 2.
//
// The cookie here is a constant 1, so the test alone decides the cone; the reference ("intent") is
// the cone of half-angle FOV / 2 with the effect's Phong in double. The note also gives the error
// against the formula as written (does the GPU do what the HLSL says).
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "stability/case_support.h"
#include "stability/gbuffer_pass.h"

namespace fxport::stability {

namespace {

constexpr double kDistance = 5, kNear = 0.1, kFar = 100, kFov = 3.14159265358979 / 4, kPi = 3.14159265358979;
constexpr double kLightZ = -3;  // 2 units in front of the plane: the pixels see it 7..55 degrees off axis

struct SpotCase {
    double fovDegrees;
    double direction;  // S = (0, 0, direction): -1 faces the plane, +1 faces away
};

// SpotLight.fx at pixel (x, y) in double; lit decided by `inCone(SL)`. Returns false where SL is
// within 1e-5 of the threshold (the GPU may go either way).
bool spotReference(int x, int y, int n, const SpotCase& c, double threshold, bool intent, double out[4]) {
    const double s = 1 / std::tan(kFov / 2);
    const double P[3] = {pixelNdcX(x, n) * kDistance / s, pixelNdcY(y, n) * kDistance / s, -kDistance};
    double L[3] = {-P[0], -P[1], kLightZ - P[2]};
    const double len = std::sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
    for (double& v : L) v /= len;
    const double SL = L[2] * c.direction;
    // as written: SL <= LightAngleCos; intent: dot(-L, S) >= cos(FOV / 2).
    const double margin = intent ? -SL - threshold : threshold - SL;
    if (std::fabs(margin) < 1e-5) return false;
    const double N[3] = {0, 0, 1};
    if (margin < 0) {
        out[0] = out[1] = out[2] = out[3] = 0;
        return true;
    }
    const double NdotI = -L[2];
    const double R[3] = {-L[0] - 2 * NdotI * N[0], -L[1] - 2 * NdotI * N[1], -L[2] - 2 * NdotI * N[2]};
    const double rLen = std::sqrt(R[0] * R[0] + R[1] * R[1] + R[2] * R[2]);
    const double eLen = std::sqrt(P[0] * P[0] + P[1] * P[1] + P[2] * P[2]);
    const double RE = -(R[0] * P[0] + R[1] * P[1] + R[2] * P[2]) / (rLen * eLen);
    const double heightAttenuation = 1 - std::clamp(len - 100.0 / 2, 0.0, 1.0);
    out[0] = out[1] = out[2] = heightAttenuation * L[2];
    out[3] = heightAttenuation * 0.5 * std::pow(std::clamp(RE, 0.0, 1.0), double(0.2f) * 255);
    return true;
}

CaseResult runSpot(GraphicsDevice& device, Effect& spot, const GBufferTargets& g, const SpotCase& c, bool fixed, int n) {
    CaseResult r;
    r.group = "spot-cone";
    char name[64];
    std::snprintf(name, sizeof name, "FOV %g deg, %s", c.fovDegrees, c.direction < 0 ? "facing plane" : "facing away");
    r.name = name;
    r.variant = fixed ? "LightAngleCos = -cos(FOV/2) (host)" : "as written";
    r.relative = false;
    const double fov = c.fovDegrees * kPi / 180;
    const float lightAngleCos = fixed ? -float(std::cos(fov / 2)) : float(std::cos(fov));
    const Vector3 light(0, 0, float(kLightZ)), S(0, 0, float(c.direction));
    const Matrix projection = Matrix::CreatePerspectiveFieldOfView(float(kFov), 1.0f, float(kNear), float(kFar));
    Texture2D cookie(device, 1, 1, false, SurfaceFormat::Single), shadow(device, 1, 1, false, SurfaceFormat::Single);
    cookie.SetData(std::vector<float>{1.0f});
    shadow.SetData(std::vector<float>{1.0f});
    spot.Parameters["inverseView"].SetValue(Matrix::Identity);
    spot.Parameters["InverseViewProjection"].SetValue(Matrix::Invert(projection));
    spot.Parameters["CameraPosition"].SetValue(Vector3(0, 0, 0));
    spot.Parameters["LightViewProjection"].SetValue(Matrix::CreateLookAt(light, light + S, Vector3::Up) *
                                                    Matrix::CreatePerspectiveFieldOfView(float(fov), 1.0f, 1.0f, 100.0f));
    spot.Parameters["LightPosition"].SetValue(light);
    spot.Parameters["LightColor"].SetValue(Vector4(1, 1, 1, 1));
    spot.Parameters["LightIntensity"].SetValue(1.0f);
    spot.Parameters["S"].SetValue(S);
    spot.Parameters["LightAngleCos"].SetValue(lightAngleCos);
    spot.Parameters["LightHeight"].SetValue(100.0f);
    spot.Parameters["Shadows"].SetValue(false);
    spot.Parameters["shadowMapSize"].SetValue(1.0f);
    spot.Parameters["DepthPrecision"].SetValue(100.0f);
    spot.Parameters["DepthBias"].SetValue(1.0f / 2000.0f);
    RenderTarget2D lightMap(device, n, n, false, SurfaceFormat::Vector4, DepthFormat::None);
    lightMap.Name = "LightMap (Vector4)";
    LightInputs in;
    in.albedo = g.albedo.get(), in.normals = g.normals.get(), in.depth = g.depth.get(), in.slot3 = &cookie, in.slot4 = &shadow;
    drawLightOverTarget(device, spot, lightMap, in, "SpotLight", r);

    const std::vector<Vector4> lit = lightMap.GetDataAsVector4();
    Accumulator intentError;
    double formulaError = 0;
    int litIntent = 0, litGpu = 0, wrong = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const Vector4 t = lit[std::size_t(y) * std::size_t(n) + std::size_t(x)];
            if (!(std::isfinite(t.X) && std::isfinite(t.Y) && std::isfinite(t.Z) && std::isfinite(t.W))) continue;
            const double got[4] = {t.X, t.Y, t.Z, t.W};
            auto error = [&](const double ref[4]) {
                double e = 0;
                for (int k = 0; k < 4; ++k) e = std::fmax(e, std::fabs(got[k] - ref[k]));
                return e;
            };
            const bool gpuLit = got[0] != 0 || got[3] != 0;
            litGpu += gpuLit;
            double ref[4];
            if (spotReference(x, y, n, c, double(lightAngleCos), false, ref)) formulaError = std::fmax(formulaError, error(ref));
            if (spotReference(x, y, n, c, std::cos(fov / 2), true, ref)) {
                const bool refLit = ref[0] != 0 || ref[3] != 0;
                litIntent += refLit;
                wrong += refLit != gpuLit;
                intentError.add(error(ref));
            }
        }
    intentError.into(r);
    char note[320];
    std::snprintf(note, sizeof note,
                  "spot at (0, 0, -3), S = (0, 0, %g), LightAngleCos = %.7g, cookie 1; pixels lit: %d in the cone of "
                  "half-angle FOV/2, %d by the GPU, %d wrong; error vs the cone (max |channel|); vs the formula as "
                  "set: %.3g",
                  c.direction, double(lightAngleCos), litIntent, litGpu, wrong, formulaError);
    r.note = note;
    return r;
}

}  // namespace

void runSpotConeCases(GraphicsDevice& device, const SuiteOptions& options, std::vector<CaseResult>& results) {
    const std::string fx = options.hlslDir + "/xna-deferred/";
    Effect gbuffer(device, fx + "GBuffer.fx");
    Effect spot(device, fx + "SpotLight.fx");
    CaseResult gbufferFindings;
    GBufferQuad q;
    q.distance = kDistance;
    q.halfExtent = kDistance;
    q.projection = Matrix::CreatePerspectiveFieldOfView(float(kFov), 1.0f, float(kNear), float(kFar));
    const GBufferTargets g = drawGBufferQuad(device, gbuffer, q, options.size, gbufferFindings);
    const SpotCase cases[] = {{0.1, -1}, {45, -1}, {90, -1}, {150, -1}, {179.9, -1}, {45, 1}};
    for (const SpotCase& c : cases)
        for (bool fixed : {false, true}) results.push_back(runSpot(device, spot, g, c, fixed, options.size));
}

}  // namespace fxport::stability
