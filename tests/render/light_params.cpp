#include "light_params.h"

#include <cmath>

#include "render_harness.h"

namespace fxport::render_test {

DirectionalLightParams directionalParams(const TestCamera& camera, const DirectionalLightSetup& light) {
    DirectionalLightParams q;
    q.inverseViewProjection = toM4(Matrix::Invert(camera.View * camera.Projection));
    q.inverseView = toM4(Matrix::Invert(camera.View));
    q.cameraPosition = toV3(camera.Position);
    q.L = toV3(Vector3::Normalize(light.Direction));
    q.lightColor = toV4(light.Color);
    q.lightIntensity = light.Intensity;
    q.gbufferTextureSize = {kWidth, kHeight};
    return q;
}

SpotLightParams spotParams(const TestCamera& camera, const SpotLightSetup& light) {
    SpotLightParams q;
    q.inverseView = toM4(Matrix::Invert(camera.View));
    q.inverseViewProjection = toM4(Matrix::Invert(camera.View * camera.Projection));
    q.lightViewProjection = toM4(light.View * light.Projection);
    q.cameraPosition = toV3(camera.Position);
    q.lightPosition = toV3(light.Position);
    q.S = toV3(light.Direction);
    q.lightColor = toV4(light.Color);
    q.lightIntensity = light.Intensity;
    q.lightAngleCos = light.LightAngleCos();
    q.lightHeight = light.FarPlane;
    q.gbufferTextureSize = {kWidth, kHeight};
    q.shadows = light.Shadows;
    q.shadowMapSize = light.ShadowMapResolution;
    q.depthPrecision = light.FarPlane;
    q.depthBias = light.DepthBias;
    return q;
}

PointLightParams pointParams(const TestCamera& camera, const PointLightSetup& light) {
    PointLightParams q;
    q.inverseView = toM4(Matrix::Invert(camera.View));
    q.inverseViewProjection = toM4(Matrix::Invert(camera.View * camera.Projection));
    q.cameraPosition = toV3(camera.Position);
    q.lightPosition = toV3(light.Position);
    q.lightRadius = light.Radius;
    q.lightColor = toV4(light.Color);
    q.lightIntensity = light.Intensity;
    q.gbufferTextureSize = {kWidth, kHeight};
    q.shadows = light.Shadows;
    q.depthPrecision = light.Radius;
    q.depthBias = light.DepthBias();
    q.shadowMapSize = light.ShadowMapResolution;
    return q;
}

Cull spotCull(const TestCamera& camera, const SpotLightSetup& light) {
    float SL = std::fabs(Vector3::Dot(camera.Position - light.Position, light.Direction));
    return SL < light.LightAngleCos() ? Cull::CounterClockwiseFace : Cull::ClockwiseFace;
}

Cull pointCull(const TestCamera& camera, const PointLightSetup& light) {
    Vector3 diff = camera.Position - light.Position;
    float cameraToLight = float(std::sqrt(float(Vector3::Dot(diff, diff)))) / 100.0f;
    return cameraToLight <= light.Radius ? Cull::ClockwiseFace : Cull::CounterClockwiseFace;
}

}  // namespace fxport::render_test
