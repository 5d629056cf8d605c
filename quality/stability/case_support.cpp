#include "stability/case_support.h"

#include <algorithm>

namespace fxport::stability {

void takeFindings(const std::vector<NonFiniteTarget>& found, CaseResult& r) {
    for (const NonFiniteTarget& f : found) {
        r.nonFinite += f.count;
        if (!r.first) r.first = f;
    }
}

GBufferTextures::GBufferTextures(GraphicsDevice& device, int size, const std::vector<Vector4>& albedoTexels,
                                 const std::vector<Vector4>& normalTexels, const std::vector<float>& depthTexels)
    : albedo(device, size, size, false, SurfaceFormat::Vector4),
      normals(device, size, size, false, SurfaceFormat::Vector4),
      depth(device, size, size, false, SurfaceFormat::Single) {
    albedo.SetData(albedoTexels);
    normals.SetData(normalTexels);
    depth.SetData(depthTexels);
}

void drawFullTargetQuad(GraphicsDevice& device) {
    static const VertexPositionTexture v[6] = {
        {Vector3(-1, 1, 0.5f), Vector2(0, 0)},  {Vector3(1, 1, 0.5f), Vector2(1, 0)}, {Vector3(-1, -1, 0.5f), Vector2(0, 1)},
        {Vector3(-1, -1, 0.5f), Vector2(0, 1)}, {Vector3(1, 1, 0.5f), Vector2(1, 0)}, {Vector3(1, -1, 0.5f), Vector2(1, 1)}};
    device.DrawUserPrimitives(PrimitiveType::TriangleList, v, 0, 2);
}

Accumulator errorAgainstZero(RenderTarget2D& target) {
    Accumulator acc;
    for (const Vector4& t : target.GetDataAsVector4()) {
        const float c[4] = {t.X, t.Y, t.Z, t.W};
        double worst = 0;
        bool finite = true;
        for (float x : c) finite = finite && std::isfinite(x), worst = std::fmax(worst, std::fabs(double(x)));
        if (finite) acc.add(worst);
    }
    return acc;
}

void setUnshadowedPointLight(Effect& pointLight, const Matrix& inverseView, const Matrix& inverseViewProjection,
                             Vector3 camera, Vector3 light, float radius) {
    auto& p = pointLight.Parameters;
    p["inverseView"].SetValue(inverseView);
    p["InverseViewProjection"].SetValue(inverseViewProjection);
    p["CameraPosition"].SetValue(camera);
    p["LightPosition"].SetValue(light);
    p["LightRadius"].SetValue(radius);
    p["LightColor"].SetValue(Vector4(1, 1, 1, 1));
    p["LightIntensity"].SetValue(1.0f);
    p["Shadows"].SetValue(false);
    p["DepthPrecision"].SetValue(std::fmax(radius, 1e-3f));
    p["DepthBias"].SetValue(1.0f / 2000.0f);
    p["shadowMapSize"].SetValue(1.0f);
}

UnitShadowCube::UnitShadowCube(GraphicsDevice& device) : cube(device, 1, false, SurfaceFormat::Single) {
    for (int f = 0; f < 6; ++f) {
        const float one = 1.0f;
        cube.SetData(CubeMapFace(f), &one, 1);
    }
}

void drawLightOverTarget(GraphicsDevice& device, Effect& effect, RenderTarget2D& target, const LightInputs& inputs,
                         const std::string& passName, CaseResult& r) {
    FiniteCheck check(device);
    check.beginPass(passName);
    device.SetRenderTarget(target);
    device.Clear(Color::TransparentBlack);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::None;
    device.RasterizerState = RasterizerState::CullNone;
    effect.Parameters["World"].SetValue(Matrix::Identity);
    effect.Parameters["View"].SetValue(Matrix::Identity);
    effect.Parameters["Projection"].SetValue(Matrix::Identity);
    effect.Parameters["GBufferTextureSize"].SetValue(Vector2(float(target.Width()), float(target.Height())));
    effect.CurrentTechnique->Passes[0].Apply();
    device.Textures[0] = inputs.albedo;
    device.Textures[1] = inputs.normals;
    device.Textures[2] = inputs.depth;
    device.Textures[3] = inputs.slot3;
    device.Textures[4] = inputs.slot4;
    for (int slot = 0; slot < 5; ++slot) device.SamplerStates[slot] = SamplerState::PointClamp;
    drawFullTargetQuad(device);
    device.SetRenderTarget(nullptr);
    for (int slot = 0; slot < 5; ++slot) device.Textures[slot] = nullptr;
    takeFindings(check.endPass(), r);
}

void pointLightReference(const PointLightScene& scene, int x, int y, int n, const double N[3], double specularIntensity,
                         double specularPower, double out[4]) {
    const double s = 1 / std::tan(scene.fov / 2), D = scene.distance;
    const double P[3] = {pixelNdcX(x, n) * D / s, pixelNdcY(y, n) * D / s, -D};
    double L[3] = {scene.light[0] - P[0], scene.light[1] - P[1], scene.light[2] - P[2]};
    const double len = std::sqrt(L[0] * L[0] + L[1] * L[1] + L[2] * L[2]);
    // saturate(1 - max(.01, |L|) / (LightRadius / 2)): radius 0 gives 1 - Inf = -Inf, saturated to 0.
    const double ratio = scene.radius > 0 ? std::fmax(0.01, len) / (scene.radius / 2) : INFINITY;
    const double attenuation = std::clamp(1 - ratio, 0.0, 1.0);
    for (double& c : L) c /= len;
    const double NdotI = -(N[0] * L[0] + N[1] * L[1] + N[2] * L[2]);  // reflect(-L, N) = -L - 2 dot(N, -L) N
    double R[3] = {-L[0] - 2 * NdotI * N[0], -L[1] - 2 * NdotI * N[1], -L[2] - 2 * NdotI * N[2]};
    const double rLen = std::sqrt(R[0] * R[0] + R[1] * R[1] + R[2] * R[2]);
    const double eLen = std::sqrt(P[0] * P[0] + P[1] * P[1] + P[2] * P[2]);
    const double RE = -(R[0] * P[0] + R[1] * P[1] + R[2] * P[2]) / (rLen * eLen);  // E = normalize(camera - P)
    const double NL = N[0] * L[0] + N[1] * L[1] + N[2] * L[2];
    const double specular = specularIntensity * std::pow(std::clamp(RE, 0.0, 1.0), specularPower);
    out[0] = out[1] = out[2] = attenuation * NL;
    out[3] = attenuation * specular;
}

std::vector<Vector4> readBack(RenderTarget2D& target) { return target.GetDataAsVector4(); }

}  // namespace fxport::stability
