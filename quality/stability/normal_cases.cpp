// Zero-length, denormal and tiny vertex normals through GBuffer.fx into a lit pixel of
// PointLight.fx.
//
// GBuffer.fx normalizes the vertex normal in its vertex shader (TBN[2] = normalize(N *
// WorldViewIT)) and again in its pixel shader (normalize(mul(tangent-space normal, TBN)), then
// encode()). normalize(0) is x * inversesqrt(0) = 0 * Inf = NaN in GLSL and on D3D9 hardware alike;
// a normal of length 1e-20 squares to 1e-40, which float32 flushes or underflows the same way; a
// denormal (1e-40) normal too. The NaN reaches the normals target: a float target keeps it and the
// light pass turns it into a NaN light; the tutorial's Rgba64 stores NaN as 0 (GL), which decodes to
// (-1, -1, -1): a finite but wrong, over-long normal -- invisible to any NaN check.
//
// Fix (runtime, opt-in, no edit of the effect): GBuffer.fx compiled with a function-like define
// that scales by the largest component before normalizing and keeps a zero vector zero:
//   normalize(v) -> (m(v) > 0 ? normalize(v / max(m(v), 1e-30)) : v),  m(v) = max(|v.x|, |v.y|, |v.z|)
// so tiny and denormal normals keep their direction and a zero normal stays 0: decoded 0, no
// diffuse light (NL = 0), the specular of reflect(-L, 0) = -L. The reference is that: the intended
// normal (0, 0, 1) for every non-zero input, 0 for the zero one.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>

#include "stability/case_support.h"
#include "stability/gbuffer_pass.h"

namespace fxport::stability {

namespace {

constexpr double kDistance = 5, kNear = 0.1, kFar = 100, kFov = 3.14159265358979 / 4, kRadius = 20;
const double kLight[3] = {1, 2, -3};
const PointLightScene kScene{kDistance, kFov, {kLight[0], kLight[1], kLight[2]}, kRadius};

struct NormalInput {
    const char* name;
    float z;          // vertex normal (0, 0, z)
    bool hasDirection;
};

CaseResult runNormal(GraphicsDevice& device, Effect& gbuffer, Effect& pointLight, const NormalInput& input,
                     SurfaceFormat format, const std::string& variant, int n) {
    CaseResult r;
    r.group = "normals";
    r.name = std::string(input.name) + " " + surfaceFormatName(format);
    r.variant = variant;
    r.relative = false;
    GBufferQuad q;
    q.distance = kDistance;
    q.halfExtent = kDistance;
    q.normal = Vector3(0, 0, input.z);
    q.normalFormat = format;
    q.projection = Matrix::CreatePerspectiveFieldOfView(float(kFov), 1.0f, float(kNear), float(kFar));
    GBufferTargets g = drawGBufferQuad(device, gbuffer, q, n, r);

    UnitShadowCube shadow(device);
    setUnshadowedPointLight(pointLight, Matrix::Identity, Matrix::Invert(q.projection), Vector3(0, 0, 0),
                            Vector3(float(kLight[0]), float(kLight[1]), float(kLight[2])), float(kRadius));
    RenderTarget2D lightMap(device, n, n, false, SurfaceFormat::Vector4, DepthFormat::None);
    lightMap.Name = "LightMap (Vector4)";
    LightInputs in;
    in.albedo = g.albedo.get(), in.normals = g.normals.get(), in.depth = g.depth.get(), in.slot4 = &shadow.cube;
    drawLightOverTarget(device, pointLight, lightMap, in, "PointLight", r);

    // A denormal input may be flushed to 0 before any arithmetic (GLSL allows it; D3D10+ requires it
    // for float32): then the zero normal's result is right too, and the closer of the two counts.
    const double N[3] = {0, 0, input.hasDirection ? 1.0 : 0.0}, zero[3] = {0, 0, 0};
    const bool mayFlush = input.z != 0 && std::fabs(input.z) < FLT_MIN;
    int flushed = 0;
    const double specularPower = double(q.specularPower) * 255;
    const std::vector<Vector4> lit = lightMap.GetDataAsVector4();
    const std::vector<Vector4> stored = g.normals->GetDataAsVector4();
    Accumulator acc;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const Vector4 t = lit[std::size_t(y) * std::size_t(n) + std::size_t(x)];
            if (!(std::isfinite(t.X) && std::isfinite(t.Y) && std::isfinite(t.Z) && std::isfinite(t.W))) continue;
            const double got[4] = {t.X, t.Y, t.Z, t.W};
            auto errorFor = [&](const double normal[3]) {
                double ref[4], worst = 0;
                pointLightReference(kScene, x, y, n, normal, q.specularIntensity, specularPower, ref);
                for (int c = 0; c < 4; ++c) worst = std::fmax(worst, std::fabs(got[c] - ref[c]));
                return worst;
            };
            double e = errorFor(N);
            if (mayFlush && errorFor(zero) < e) e = errorFor(zero), ++flushed;
            acc.add(e);
        }
    acc.into(r);
    const Vector4 s0 = stored[0];
    char note[512];
    std::snprintf(note, sizeof note,
                  "vertex normal (0, 0, %g); G-buffer normal texel (%.4g, %.4g, %.4g) (decodes to (%.3g, %.3g, %.3g)); "
                  "light map vs PointLight.fx in double with normal (0, 0, %g)%s; error = max |channel|",
                  double(input.z), double(s0.X), double(s0.Y), double(s0.Z), 2.0 * s0.X - 1, 2.0 * s0.Y - 1,
                  2.0 * s0.Z - 1, N[2], flushed ? " or, the denormal flushed to 0 (closer here), normal 0" : "");
    r.note = note;
    return r;
}

}  // namespace

void runNormalCases(GraphicsDevice& device, const SuiteOptions& options, std::vector<CaseResult>& results) {
    const std::string fx = options.hlslDir + "/xna-deferred/";
    Effect gbuffer(device, fx + "GBuffer.fx");
    EffectOptions safe;
    safe.defines.push_back(
        {"normalize(v)",
         "((max(max(abs((v).x), abs((v).y)), abs((v).z)) > 0) ? "
         "normalize((v) / max(max(max(abs((v).x), abs((v).y)), abs((v).z)), 1e-30)) : (v))"});
    Effect gbufferSafe(device, fx + "GBuffer.fx", safe);
    Effect pointLight(device, fx + "PointLight.fx");
    const NormalInput inputs[] = {
        {"unit", 1.0f, true}, {"zero", 0.0f, false}, {"denormal 1e-40", 1e-40f, true}, {"tiny 1e-20", 1e-20f, true}};
    for (const NormalInput& input : inputs)
        for (SurfaceFormat format : {SurfaceFormat::Vector4, SurfaceFormat::Rgba64}) {
            results.push_back(runNormal(device, gbuffer, pointLight, input, format, "as written", options.size));
            results.push_back(runNormal(device, gbufferSafe, pointLight, input, format,
                                        "#define normalize: scaled, 0 stays 0", options.size));
        }
}

}  // namespace fxport::stability
