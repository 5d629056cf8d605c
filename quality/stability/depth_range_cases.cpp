// Near/far ratios 1e2..1e7 through GBuffer.fx's depth (z/w into a Vector2 target) and what
// PointLight.fx reconstructs from it (Position = (ndc, depth, 1) * InverseViewProjection, / w).
//
// The position the light pass reconstructs is measured through the effect itself: the light sits
// at the camera with radius R, so its attenuation 1 - |P'|/(R/2) is the reconstructed distance
// |P'|; each pixel's G-buffer normal is the true direction to the light (NL = 1 up to the
// reference's known cosine), the specular intensity 0. |P'| is compared with the plane's true
// distance in double.
//
// As written (XNA's projection), z/w = f/(f-n) (1 - n/D) crowds against 1: float32 resolves 2^-24
// there, so the reconstructed distance moves in steps of about D^2/n * 6e-8. Fix (host, opt-in):
// a reversed-Z projection (near -> 1, far -> 0; M33 = n/(f-n), M43 = n f/(f-n)): z/w ~ n/D keeps
// float32's relative precision, and the light pass needs nothing else (it inverts whatever
// projection the host gives). The host then depth-tests GreaterEqual and clears depth to 0 -- the
// effects are unchanged.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "stability/case_support.h"
#include "stability/gbuffer_pass.h"

namespace fxport::stability {

namespace {

constexpr double kNear = 0.1;
constexpr double kFov = 3.14159265358979 / 4;

Matrix projectionFor(double farPlane, bool reversed) {
    Matrix p = Matrix::CreatePerspectiveFieldOfView(float(kFov), 1.0f, float(kNear), float(farPlane));
    if (reversed) {
        p.M33 = float(kNear / (farPlane - kNear));
        p.M43 = float(kNear * farPlane / (farPlane - kNear));
    }
    return p;
}

CaseResult runDepthRange(GraphicsDevice& device, Effect& gbuffer, Effect& pointLight, double ratio, bool reversed, int n) {
    CaseResult r;
    r.group = "near-far";
    char name[64];
    const double farPlane = kNear * ratio, D = farPlane / 2;  // the plane halfway to the far plane
    std::snprintf(name, sizeof name, "f/n=1e%d, D=f/2", int(std::lround(std::log10(ratio))));
    r.name = name;
    r.variant = reversed ? "reversed-Z projection (host)" : "as written";
    r.relative = false;

    GBufferQuad q;
    q.distance = D;
    q.halfExtent = D;  // tan(fov/2) = 0.414: the quad covers the view
    q.projection = projectionFor(farPlane, reversed);
    GBufferTargets g = drawGBufferQuad(device, gbuffer, q, n, r);

    // True positions of the pixels' sample points on the plane (double), s = 1/tan(fov/2).
    const double s = 1 / std::tan(kFov / 2);
    auto truePoint = [&](int x, int y, double out[3]) {
        out[0] = pixelNdcX(x, n) * D / s, out[1] = pixelNdcY(y, n) * D / s, out[2] = -D;
    };
    // Normal texel (i, j) serves pixel (i + 1, j + 1): the light pass reads the G-buffer one texel up
    // and left (UV - 1/GBufferTextureSize, as written).
    std::vector<Vector4> normals(std::size_t(n) * std::size_t(n)), albedo(normals.size(), Vector4(1, 1, 1, 0));
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            double p[3];
            truePoint(i + 1, j + 1, p);
            const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            normals[std::size_t(j) * std::size_t(n) + std::size_t(i)] =
                Vector4(float((1 - p[0] / len) / 2), float((1 - p[1] / len) / 2), float((1 - p[2] / len) / 2), 0);
        }
    Texture2D albedoTexture(device, n, n, false, SurfaceFormat::Vector4), normalTexture(device, n, n, false, SurfaceFormat::Vector4);
    albedoTexture.SetData(albedo);
    normalTexture.SetData(normals);
    UnitShadowCube shadow(device);

    const double R = 4 * farPlane;
    setUnshadowedPointLight(pointLight, Matrix::Identity, Matrix::Invert(q.projection), Vector3(0, 0, 0), Vector3(0, 0, 0),
                            float(R));
    RenderTarget2D lightMap(device, n, n, false, SurfaceFormat::Vector4, DepthFormat::None);
    lightMap.Name = "LightMap (Vector4)";
    LightInputs in;
    in.albedo = &albedoTexture, in.normals = &normalTexture, in.depth = g.depth.get(), in.slot4 = &shadow.cube;
    drawLightOverTarget(device, pointLight, lightMap, in, "PointLight", r);

    // Stored depth against z/w in double; reconstructed distance against |P|.
    const double A = reversed ? kNear / (farPlane - kNear) : farPlane / (kNear - farPlane);
    const double B = reversed ? kNear * farPlane / (farPlane - kNear) : kNear * farPlane / (kNear - farPlane);
    const double zOverW = (-D * A + B) / D;
    double depthError = 0;
    for (const Vector4& t : g.depth->GetDataAsVector4())
        if (std::isfinite(t.X)) depthError = std::fmax(depthError, std::fabs(t.X - zOverW));
    const std::vector<Vector4> lit = lightMap.GetDataAsVector4();
    Accumulator acc;
    int saturatedAtZero = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const float out = lit[std::size_t(y) * std::size_t(n) + std::size_t(x)].X;
            if (!std::isfinite(out)) continue;
            double p[3];
            truePoint(x, y, p);
            const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
            const Vector4 nt = normals[std::size_t(std::max(y - 1, 0)) * std::size_t(n) + std::size_t(std::max(x - 1, 0))];
            const double N[3] = {2.0 * nt.X - 1, 2.0 * nt.Y - 1, 2.0 * nt.Z - 1};
            const double NL = -(N[0] * p[0] + N[1] * p[1] + N[2] * p[2]) / len;
            if (out <= 0) ++saturatedAtZero;  // |P'| >= R/2: the error is at least what is counted
            const double measured = (1 - double(out) / NL) * R / 2;
            acc.add(std::fabs(measured - len));
        }
    acc.into(r);
    char note[256];
    std::snprintf(note, sizeof note,
                  "plane at D = %.3g (n = 0.1, f = %.3g); stored z/w = %.9f, max |GPU - double| = %.3g; "
                  "reconstructed |P| error max %.3g world units = %.3g D%s",
                  D, farPlane, zOverW, depthError, acc.worst, acc.worst / D,
                  saturatedAtZero ? " (some at the attenuation's floor: at least this)" : "");
    r.note = note;
    return r;
}

}  // namespace

void runDepthRangeCases(GraphicsDevice& device, const SuiteOptions& options, std::vector<CaseResult>& results) {
    const std::string fx = options.hlslDir + "/xna-deferred/";
    Effect gbuffer(device, fx + "GBuffer.fx");
    Effect pointLight(device, fx + "PointLight.fx");
    for (double ratio : {1e2, 1e3, 1e4, 1e5, 1e6, 1e7})
        for (bool reversed : {false, true})
            results.push_back(runDepthRange(device, gbuffer, pointLight, ratio, reversed, options.size));
}

}  // namespace fxport::stability
