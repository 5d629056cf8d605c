// xna-deferred PointLight.fx on lit pixels: light radius -> 0 and -> 1e6, and the camera exactly at
// the light, inside its volume.
//
// Radius: Attenuation = saturate(1 - max(.01, |L|) / (LightRadius / 2)). Radius 0 divides by 0:
// 1 - Inf = -Inf, saturated to 0 on IEEE hardware (GLSL does not promise x / 0 = Inf; the max(.01)
// keeps it from 0 / 0). The reference is the same formula in double.
//
// Camera inside the volume: the demos draw the light's sphere with its inner faces (CullClockwise)
// when the camera is inside (pointlights: |camera - light| < radius + near). At the light's centre
// the inner faces surround the camera and every pixel runs the light once -- unless the sphere is
// bigger than the far plane: then all of it is clipped and the light vanishes (radius 1e6, far
// 100). Fix (host, opt-in): when the camera is inside, draw the light as a full-screen quad
// (World = View = Projection = identity; the effect's ScreenPosition is then the quad's clip
// position, and it reconstructs positions from the G-buffer as before).
#include <cmath>
#include <cstdio>

#include "stability/case_support.h"
#include "stability/gbuffer_pass.h"

namespace fxport::stability {

namespace {

constexpr double kDistance = 5, kNear = 0.1, kFar = 100, kFov = 3.14159265358979 / 4;

enum class Volume { Quad, SphereInside, SphereOutside };

// A unit UV sphere, outward faces clockwise as seen from outside (XNA's front faces).
std::vector<VertexPositionTexture> unitSphere(int rings, int segments) {
    std::vector<VertexPositionTexture> out;
    const double pi = 3.14159265358979;
    auto point = [&](int ring, int seg) {
        const double t = pi * ring / rings, p = 2 * pi * seg / segments;
        return Vector3(float(std::sin(t) * std::cos(p)), float(std::cos(t)), float(std::sin(t) * std::sin(p)));
    };
    auto add = [&](Vector3 a, Vector3 b, Vector3 c) {
        const Vector3 n = Vector3::Cross(b - a, c - a);
        if (n.Length() < 1e-12f) return;  // degenerate at the poles
        if (Vector3::Dot(n, a + b + c) > 0) std::swap(b, c);  // counter-clockwise from outside: flip
        for (Vector3 v : {a, b, c}) out.push_back({v, Vector2(0, 0)});
    };
    for (int r = 0; r < rings; ++r)
        for (int s = 0; s < segments; ++s) {
            add(point(r, s), point(r + 1, s), point(r + 1, s + 1));
            add(point(r, s), point(r + 1, s + 1), point(r, s + 1));
        }
    return out;
}

struct PointCase {
    std::string name;
    double light[3];
    double radius;
};

CaseResult runPoint(GraphicsDevice& device, Effect& pointLight, const GBufferTargets& g, const PointCase& c, Volume volume,
                    const std::string& variant, int n) {
    CaseResult r;
    r.group = "point-light";
    r.name = c.name;
    r.variant = variant;
    r.relative = false;
    const Matrix projection = Matrix::CreatePerspectiveFieldOfView(float(kFov), 1.0f, float(kNear), float(kFar));
    const Vector3 light(float(c.light[0]), float(c.light[1]), float(c.light[2]));
    UnitShadowCube shadow(device);
    setUnshadowedPointLight(pointLight, Matrix::Identity, Matrix::Invert(projection), Vector3(0, 0, 0), light, float(c.radius));
    RenderTarget2D lightMap(device, n, n, false, SurfaceFormat::Vector4, DepthFormat::None);
    lightMap.Name = "LightMap (Vector4)";
    LightInputs in;
    in.albedo = g.albedo.get(), in.normals = g.normals.get(), in.depth = g.depth.get(), in.slot4 = &shadow.cube;
    if (volume == Volume::Quad) {
        drawLightOverTarget(device, pointLight, lightMap, in, "PointLight", r);
    } else {
        // The light's sphere: World = Scale(radius) * Translation(light), the camera's View/Projection.
        static const std::vector<VertexPositionTexture> sphere = unitSphere(12, 24);
        FiniteCheck check(device);
        check.beginPass("PointLight");
        device.SetRenderTarget(lightMap);
        device.Clear(Color::TransparentBlack);
        device.BlendState = BlendState::Opaque;
        device.DepthStencilState = DepthStencilState::None;
        device.RasterizerState =
            volume == Volume::SphereInside ? RasterizerState::CullClockwise : RasterizerState::CullCounterClockwise;
        pointLight.Parameters["World"].SetValue(Matrix::CreateScale(float(c.radius)) * Matrix::CreateTranslation(light));
        pointLight.Parameters["View"].SetValue(Matrix::Identity);
        pointLight.Parameters["Projection"].SetValue(projection);
        pointLight.Parameters["GBufferTextureSize"].SetValue(Vector2(float(n), float(n)));
        pointLight.CurrentTechnique->Passes[0].Apply();
        device.Textures[0] = in.albedo, device.Textures[1] = in.normals, device.Textures[2] = in.depth;
        device.Textures[4] = in.slot4;
        for (int slot = 0; slot < 5; ++slot) device.SamplerStates[slot] = SamplerState::PointClamp;
        device.DrawUserPrimitives(PrimitiveType::TriangleList, sphere.data(), 0, int(sphere.size() / 3));
        device.SetRenderTarget(nullptr);
        for (int slot = 0; slot < 5; ++slot) device.Textures[slot] = nullptr;
        takeFindings(check.endPass(), r);
    }

    const PointLightScene scene{kDistance, kFov, {c.light[0], c.light[1], c.light[2]}, c.radius};
    const double N[3] = {0, 0, 1};
    const std::vector<Vector4> lit = lightMap.GetDataAsVector4();
    Accumulator acc;
    int litRef = 0, litGpu = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const Vector4 t = lit[std::size_t(y) * std::size_t(n) + std::size_t(x)];
            if (!(std::isfinite(t.X) && std::isfinite(t.Y) && std::isfinite(t.Z) && std::isfinite(t.W))) continue;
            double ref[4];
            pointLightReference(scene, x, y, n, N, 0.5, double(0.2f) * 255, ref);
            const double got[4] = {t.X, t.Y, t.Z, t.W};
            double worst = 0;
            for (int k = 0; k < 4; ++k) worst = std::fmax(worst, std::fabs(got[k] - ref[k]));
            litRef += ref[0] != 0 || ref[3] != 0;
            litGpu += got[0] != 0 || got[3] != 0;
            acc.add(worst);
        }
    acc.into(r);
    char note[256];
    std::snprintf(note, sizeof note,
                  "light (%g, %g, %g) radius %g, camera at the origin, G-buffer plane at z = -5 (GBuffer.fx); pixels lit: "
                  "%d by the reference, %d by the GPU; error = max |channel| vs PointLight.fx in double",
                  c.light[0], c.light[1], c.light[2], c.radius, litRef, litGpu);
    r.note = note;
    return r;
}

}  // namespace

void runPointLightCases(GraphicsDevice& device, const SuiteOptions& options, std::vector<CaseResult>& results) {
    const std::string fx = options.hlslDir + "/xna-deferred/";
    Effect gbuffer(device, fx + "GBuffer.fx");
    Effect pointLight(device, fx + "PointLight.fx");
    const int n = options.size;
    CaseResult gbufferFindings;  // the G-buffer pass is checked by the normals group; a clean one here
    GBufferQuad q;
    q.distance = kDistance;
    q.halfExtent = kDistance;
    q.projection = Matrix::CreatePerspectiveFieldOfView(float(kFov), 1.0f, float(kNear), float(kFar));
    const GBufferTargets g = drawGBufferQuad(device, gbuffer, q, n, gbufferFindings);

    // Radius -> 0 and -> 1e6, the light in front of the plane (full-screen light pass).
    for (double radius : {0.0, 1e-6, 20.0, 1e6}) {
        char name[48];
        std::snprintf(name, sizeof name, "r=%g", radius);
        results.push_back(runPoint(device, pointLight, g, {name, {1, 2, -3}, radius}, Volume::Quad, "as written", n));
    }
    // The camera exactly at the light, inside its volume: the sphere's inner faces (the demos' cull
    // switch), its outer faces (no switch), and the host's full-screen quad.
    for (double radius : {20.0, 1e6}) {
        char name[48];
        std::snprintf(name, sizeof name, "camera at light, r=%g", radius);
        const PointCase c{name, {0, 0, 0}, radius};
        results.push_back(runPoint(device, pointLight, g, c, Volume::SphereInside, "sphere, CullClockwise (demos' switch)", n));
        results.push_back(runPoint(device, pointLight, g, c, Volume::SphereOutside, "sphere, CullCounterClockwise (no switch)", n));
        results.push_back(runPoint(device, pointLight, g, c, Volume::Quad, "full-screen quad when inside (host)", n));
    }
}

}  // namespace fxport::stability
