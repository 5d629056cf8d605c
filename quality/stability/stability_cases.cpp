#include "stability/stability_cases.h"

#include "stability/case_support.h"

#include <cfloat>
#include <cmath>
#include <limits>
#include <memory>

namespace fxport::stability {

namespace {

// --- DepthWriter.fx: the exponential shadow map's write, exp(DepthPrecision/2 * d/DepthPrecision)
// = exp(d/2), d = distance from the light. A square caster of half-size `halfExtent`, facing the
// light at distance d, fills the target (orthographic view of it).

struct ShadowSetup {
    std::string name;
    double light[3] = {0, 0, 0};
    double distance = 10;            // caster centre = light + (0.37, -0.21, -distance)
    double halfExtent = 1.3;         // not a power of two: sample points fall between float grid steps
    SurfaceFormat format = SurfaceFormat::Single;
    int width = 32, height = 32;
    // Host-side fixes (DepthWriter.fx unchanged):
    double lightSpaceScale = 1;      // scale the world about the light by k: stored exp(k d / 2)
    bool rebase = false;             // positions relative to the light, computed in double
};

float formatMax(SurfaceFormat f) {
    return f == SurfaceFormat::HalfSingle || f == SurfaceFormat::HalfVector2 || f == SurfaceFormat::HalfVector4 ||
                   f == SurfaceFormat::HdrBlendable
               ? 65504.0f
               : FLT_MAX;
}

CaseResult runShadowWrite(GraphicsDevice& device, Effect& depthWriter, const ShadowSetup& s, const std::string& group,
                          const std::string& variant) {
    CaseResult r;
    r.group = group;
    r.name = s.name;
    r.variant = variant;
    const double k = s.lightSpaceScale;
    const double centre[3] = {s.light[0] + 0.37, s.light[1] - 0.21, s.light[2] - s.distance};

    // The host's matrices. As written: World = translation to the caster, in float, the light at
    // its float position, the camera (orthographic, looking down -z) around the caster's float
    // position. Rebased: everything relative to the light, the difference taken in double.
    Matrix world, projection;
    Vector3 lightPosition;
    const float e = float(s.halfExtent * k);
    if (s.rebase) {
        const Vector3 rel(float((centre[0] - s.light[0]) * k), float((centre[1] - s.light[1]) * k),
                          float((centre[2] - s.light[2]) * k));
        world = Matrix::CreateScale(float(k)) * Matrix::CreateTranslation(rel);
        lightPosition = Vector3(0, 0, 0);
        projection = Matrix::CreateOrthographicOffCenter(rel.X - e, rel.X + e, rel.Y - e, rel.Y + e, -rel.Z - 1.0f * float(k),
                                                         -rel.Z + 1.0f * float(k));
    } else {
        const Vector3 L{float(s.light[0]), float(s.light[1]), float(s.light[2])};
        const Vector3 C{float(centre[0]), float(centre[1]), float(centre[2])};
        // Scale about the light: v -> L + k (v - L).
        world = Matrix::CreateTranslation(C) * Matrix::CreateTranslation(-L) * Matrix::CreateScale(float(k)) *
                Matrix::CreateTranslation(L);
        lightPosition = L;
        const Vector3 c = L + (C - L) * float(k);
        projection = Matrix::CreateOrthographicOffCenter(c.X - e, c.X + e, c.Y - e, c.Y + e, -c.Z - 1.0f * float(k),
                                                         -c.Z + 1.0f * float(k));
    }

    RenderTarget2D target(device, s.width, s.height, false, s.format, DepthFormat::None);
    target.Name = std::string("shadowMap (") + surfaceFormatName(s.format) + ")";
    FiniteCheck check(device);
    check.beginPass("DepthWriter");
    device.SetRenderTarget(target);
    device.Clear(Color::TransparentBlack);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::None;
    device.RasterizerState = RasterizerState::CullNone;
    depthWriter.Parameters["World"].SetValue(world);
    depthWriter.Parameters["View"].SetValue(Matrix::Identity);
    depthWriter.Parameters["Projection"].SetValue(projection);
    depthWriter.Parameters["LightPosition"].SetValue(lightPosition);
    depthWriter.Parameters["DepthPrecision"].SetValue(float(s.distance * 2 * k));  // cancels out; the demo's far plane
    depthWriter.CurrentTechnique->Passes[0].Apply();
    // The caster in model space: a square of half-size halfExtent in z = 0 (clockwise as seen).
    const float h = float(s.halfExtent);
    VertexPositionTexture v[6] = {{Vector3(-h, h, 0), Vector2(0, 0)},  {Vector3(h, h, 0), Vector2(1, 0)},
                                  {Vector3(-h, -h, 0), Vector2(0, 1)}, {Vector3(-h, -h, 0), Vector2(0, 1)},
                                  {Vector3(h, h, 0), Vector2(1, 0)},   {Vector3(h, -h, 0), Vector2(1, 1)}};
    device.DrawUserPrimitives(PrimitiveType::TriangleList, v, 0, 2);
    device.SetRenderTarget(nullptr);
    takeFindings(check.endPass(), r);

    // Reference: pixel (i, j) shows the caster point at model (x, y) = (-h + 2h i/W, h - 2h j/H)
    // (D3D9 pixel centres, vs_3_0); stored = exp(k |C + (x, y, 0) - L| / 2), in double.
    const std::vector<Vector4> texels = target.GetDataAsVector4();
    const float top = formatMax(s.format);
    Accumulator acc, shadow;
    for (int j = 0; j < s.height; ++j) {
        for (int i = 0; i < s.width; ++i) {
            const float stored = texels[std::size_t(j) * std::size_t(s.width) + std::size_t(i)].X;
            if (!std::isfinite(stored)) continue;
            if (stored == 0) continue;  // not covered (a cleared texel; exp() >= 1 where drawn)
            if (stored == top) ++r.saturated;
            const double x = -s.halfExtent + 2 * s.halfExtent * i / s.width;
            const double y = s.halfExtent - 2 * s.halfExtent * j / s.height;
            const double dx = centre[0] + x - s.light[0], dy = centre[1] + y - s.light[1], dz = centre[2] - s.light[2];
            const double d = k * std::sqrt(dx * dx + dy * dy + dz * dz);
            const double reference = std::exp(d / 2);
            acc.add(std::fabs(stored - reference) / reference);
            // What PointLight.fx/SpotLight.fx make of it for a receiver at the caster (bias 0), in
            // float as the shader does: lZ * exp(-d/2) should be 1 (lit).
            const float factor = stored * std::exp(-float(d) / 2.0f);
            shadow.add(std::fabs(double(factor) - 1.0));
        }
    }
    acc.into(r);
    r.note = "stored exp(d/2) vs double; shadow factor lZ*exp(-d/2) max |f-1| = " + std::to_string(shadow.worst);
    if (!std::isfinite(shadow.worst) || shadow.n < acc.n) r.note += " (non-finite factors)";
    return r;
}

// --- PointLight.fx over a cleared G-buffer (Clear.fx's values: albedo 0, specular intensity 0,
// normal encoded 0.5 = zero vector, specular power 0, depth 1). Every lit term is multiplied by
// 0, so the light map must be exactly 0; but Specular = 0 * pow(saturate(dot(R, E)), 0) is
// pow(0, 0) wherever R faces away from the eye: undefined in GLSL, NaN where a driver computes
// exp2(y*log2(x)) literally (0 * -Inf), and 0 * NaN = NaN.

struct LightSetup {
    std::string name;
    Vector3 camera = Vector3(0, 2, 10);
    Vector3 light = Vector3(0, 2, 10);
    float radius = 20;
};

CaseResult runClearedGBufferLight(GraphicsDevice& device, Effect& pointLight, const LightSetup& s, int size,
                                  const std::string& variant) {
    CaseResult r;
    r.group = "pow00";
    r.name = s.name;
    r.variant = variant;
    r.relative = false;
    const std::size_t n = std::size_t(size) * std::size_t(size);
    Texture2D albedo(device, size, size, false, SurfaceFormat::Color);
    // RGBA32F, so that the cleared normal decodes to exactly 0 (a Color target stores Clear.fx's
    // 0.5 as 128/255, which decodes to 0.0039 and lights cleared pixels a little: NL != 0).
    Texture2D normals(device, size, size, false, SurfaceFormat::Vector4);
    Texture2D depth(device, size, size, false, SurfaceFormat::Single);
    UnitShadowCube shadow(device);
    albedo.SetData(std::vector<Color>(n, Color(std::uint8_t(0), std::uint8_t(0), std::uint8_t(0), std::uint8_t(0))));
    normals.SetData(std::vector<Vector4>(n, Vector4(0.5f, 0.5f, 0.5f, 0.0f)));
    depth.SetData(std::vector<float>(n, 1.0f));
    RenderTarget2D lightMap(device, size, size, false, SurfaceFormat::HdrBlendable, DepthFormat::None);
    lightMap.Name = "LightMap (HdrBlendable)";

    const Matrix view = Matrix::CreateLookAt(s.camera, Vector3(0, 0, 0), Vector3::Up);
    const Matrix projection = Matrix::CreatePerspectiveFieldOfView(MathHelper::PiOver4, 1.0f, 0.1f, 100.0f);
    // The light volume as a full-screen quad (drawLightOverTarget): every pixel is lit once.
    setUnshadowedPointLight(pointLight, Matrix::Invert(view), Matrix::Invert(view * projection), s.camera, s.light, s.radius);
    LightInputs in;
    in.albedo = &albedo, in.normals = &normals, in.depth = &depth, in.slot4 = &shadow.cube;
    drawLightOverTarget(device, pointLight, lightMap, in, "PointLight", r);

    // Reference: 0 everywhere (every term is multiplied by a cleared 0).
    errorAgainstZero(lightMap).into(r);
    r.note = "cleared G-buffer must light to exactly 0; error = max |channel|";
    return r;
}

}  // namespace

std::vector<CaseResult> runStabilityCases(GraphicsDevice& device, const SuiteOptions& options) {
    std::vector<CaseResult> results;
    const std::string fx = options.hlslDir + "/xna-deferred/";
    Effect depthWriter(device, fx + "DepthWriter.fx");
    const int n = options.size;

    // 1. Exponential shadow maps: exp(d/2) passes float16's 65504 at d = 2 ln 65504 = 22.2 and
    // float32's 3.4e38 at d = 177.4. Fix (host): scale the light's space by k so that k d stays
    // below the format's limit -- the light pass must get the same k (positions, CameraPosition,
    // LightRadius scaled about the light; DepthBias then acts at 1/k the distance).
    for (SurfaceFormat format : {SurfaceFormat::HalfSingle, SurfaceFormat::Single}) {
        const double limit = format == SurfaceFormat::Single ? 170.0 : 20.0;  // k d_max under the limit
        for (double d : {10.0, 20.0, 30.0, 100.0, 180.0, 400.0}) {
            ShadowSetup s;
            s.name = "d=" + std::to_string(int(d)) + " " + surfaceFormatName(format);
            s.distance = d;
            s.format = format;
            s.width = s.height = n;
            results.push_back(runShadowWrite(device, depthWriter, s, "exp-shadow", "as written"));
            const double reach = d + 2;  // the farthest caster the light sees in this case
            if (reach > limit) {
                s.lightSpaceScale = limit / reach;
                char variant[64];
                std::snprintf(variant, sizeof variant, "light space x%.3g", s.lightSpaceScale);
                results.push_back(runShadowWrite(device, depthWriter, s, "exp-shadow", variant));
            }
        }
    }

    // 2. Far from the origin: the same light and caster (d = 10, Single) translated by t. The
    // stored value must not depend on t. Fix (host): positions relative to the light, the
    // difference taken in double (camera/light-relative rendering).
    for (double t : {0.0, 1e4, 1e5, 1e6}) {
        ShadowSetup s;
        s.name = "t=" + (t == 0 ? std::string("0") : std::to_string(int(std::log10(t) + 0.5)).insert(0, "1e"));
        s.light[0] = s.light[1] = s.light[2] = t;
        s.distance = 10;
        s.width = s.height = n;
        results.push_back(runShadowWrite(device, depthWriter, s, "far-from-origin", "as written"));
        s.rebase = true;
        results.push_back(runShadowWrite(device, depthWriter, s, "far-from-origin", "light-relative"));
    }

    // 3. Target sizes: 1x1, and the driver's widest (max x 1), d = 10.
    {
        ShadowSetup s;
        s.distance = 10;
        s.name = "1x1";
        s.width = s.height = 1;
        results.push_back(runShadowWrite(device, depthWriter, s, "target-size", "as written"));
        if (options.largest) {
            s.width = device.maxTextureSize();
            s.height = 1;
            s.name = std::to_string(s.width) + "x1";
            results.push_back(runShadowWrite(device, depthWriter, s, "target-size", "as written"));
        }
    }

    // 4. pow(0, 0) on cleared G-buffer pixels (PointLight.fx). Fix: the runtime compiles the
    // effect with a function-like #define, pow(x, y) -> pow(max(x, 1e-30), y): pow(0, 0) becomes
    // 1 (HLSL's intent), nothing else changes by more than 1e-30^y. The cases also put the camera
    // exactly at the light, and the radius at 1e-30 and 1e6.
    Effect pointLight(device, fx + "PointLight.fx");
    EffectOptions safePow;
    safePow.defines.push_back({"pow(x, y)", "pow(max(x, 1e-30), y)"});
    Effect pointLightSafe(device, fx + "PointLight.fx", safePow);
    const LightSetup lights[] = {
        {"camera at light, r=20", Vector3(0, 2, 10), Vector3(0, 2, 10), 20.0f},
        {"camera off light, r=20", Vector3(0, 2, 10), Vector3(3, 5, 0), 20.0f},
        {"camera at light, r=1e-30", Vector3(0, 2, 10), Vector3(0, 2, 10), 1e-30f},
        {"camera at light, r=1e6", Vector3(0, 2, 10), Vector3(0, 2, 10), 1e6f},
    };
    for (const LightSetup& s : lights) {
        results.push_back(runClearedGBufferLight(device, pointLight, s, n, "as written"));
        results.push_back(runClearedGBufferLight(device, pointLightSafe, s, n, "#define pow(x,y) pow(max(x,1e-30),y)"));
    }

    runDepthRangeCases(device, options, results);
    runNormalCases(device, options, results);
    runPointLightCases(device, options, results);
    runSpotConeCases(device, options, results);
    runZimaLightCases(device, options, results);
    runUnwrapCases(device, options, results);
    return results;
}

}  // namespace fxport::stability
