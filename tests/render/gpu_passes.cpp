#include "gpu_passes.h"

#include <cmath>
#include <memory>
#include <string>

namespace fxport::render_test {

namespace {

std::string effectPath(const char* name) { return std::string(FXPORT_HLSL_DIR) + "/xna-deferred/" + name + ".fx"; }

// LightMapBS: One/One/Add for colour and alpha.
BlendState lightMapBlendState() {
    BlendState bs;
    bs.ColorSourceBlend = Blend::One;
    bs.ColorDestinationBlend = Blend::One;
    bs.ColorBlendFunction = BlendFunction::Add;
    bs.AlphaSourceBlend = Blend::One;
    bs.AlphaDestinationBlend = Blend::One;
    bs.AlphaBlendFunction = BlendFunction::Add;
    return bs;
}

}  // namespace

DeferredEffects::DeferredEffects(GraphicsDevice& device)
    : Clear(device, effectPath("Clear")), GBuffer(device, effectPath("GBuffer")), DepthWriter(device, effectPath("DepthWriter")),
      DirectionalLight(device, effectPath("DirectionalLight")), SpotLight(device, effectPath("SpotLight")),
      PointLight(device, effectPath("PointLight")), Compose(device, effectPath("Composition")), Ssao(device, effectPath("SSAO")),
      SsaoBlur(device, effectPath("SSAOBlur")), SsaoFinal(device, effectPath("SSAOFinal")) {
    for (Effect* e : {&Clear, &GBuffer, &DepthWriter, &DirectionalLight, &SpotLight, &PointLight, &Compose, &Ssao, &SsaoBlur,
                      &SsaoFinal})
        e->CurrentTechnique = e->Techniques[0];
}

DeferredEffects& deferredEffects(GraphicsDevice& device) {
    static std::unique_ptr<DeferredEffects> effects = std::make_unique<DeferredEffects>(device);
    return *effects;
}

const fxport::VertexDeclaration SceneVertex::VertexDeclaration({
    VertexElement(0, VertexElementFormat::Vector3, VertexElementUsage::Position, 0),
    VertexElement(12, VertexElementFormat::Vector3, VertexElementUsage::Normal, 0),
    VertexElement(24, VertexElementFormat::Vector2, VertexElementUsage::TextureCoordinate, 0),
    VertexElement(32, VertexElementFormat::Vector3, VertexElementUsage::Tangent, 0),
    VertexElement(44, VertexElementFormat::Vector3, VertexElementUsage::Binormal, 0),
});

GpuMesh toGpu(const Mesh& mesh) {
    GpuMesh g;
    auto v3 = [](V3 v) { return Vector3(float(v.x), float(v.y), float(v.z)); };
    for (const MeshVertex& v : mesh.vertices)
        g.vertices.push_back({v3(v.position), v3(v.normal), Vector2(float(v.uv.x), float(v.uv.y)), v3(v.tangent), v3(v.binormal)});
    for (const auto& t : mesh.triangles)
        for (int i : t) g.indices.push_back(i);
    return g;
}

void drawMesh(GraphicsDevice& device, const GpuMesh& mesh) {
    device.DrawUserIndexedPrimitives(PrimitiveType::TriangleList, mesh.vertices.data(), 0, int(mesh.vertices.size()),
                                     mesh.indices.data(), 0, int(mesh.indices.size() / 3));
}

void clearGBuffer(GraphicsDevice& device, const std::vector<RenderTargetBinding>& gbuffer) {
    DeferredEffects& fx = deferredEffects(device);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::Default;
    device.RasterizerState = RasterizerState::CullCounterClockwise;
    device.DepthStencilState = DepthStencilState::DepthRead;
    device.SetRenderTargets(gbuffer);
    fx.Clear.CurrentTechnique->Passes[0].Apply();
    FullscreenQuad fsq(device);
    fsq.Draw(device);
}

void makeGBuffer(GraphicsDevice& device, const GpuMesh& scene, const Matrix& world, const TestCamera& camera,
                 Texture2D& albedo, Texture2D& normalMap, Texture2D& specularMap) {
    DeferredEffects& fx = deferredEffects(device);
    device.DepthStencilState = DepthStencilState::Default;
    fx.GBuffer.Parameters["View"].SetValue(camera.View);
    fx.GBuffer.Parameters["Projection"].SetValue(camera.Projection);
    fx.GBuffer.Parameters["World"].SetValue(world);
    fx.GBuffer.Parameters["WorldViewIT"].SetValue(Matrix::Transpose(Matrix::Invert(world * camera.View)));
    fx.GBuffer.Parameters["Texture"].SetValue(albedo);
    fx.GBuffer.Parameters["NormalMap"].SetValue(normalMap);
    fx.GBuffer.Parameters["SpecularMap"].SetValue(specularMap);
    fx.GBuffer.CurrentTechnique->Passes[0].Apply();
    drawMesh(device, scene);
}

void drawSpotShadowMap(GraphicsDevice& device, RenderTarget2D& shadowMap, const GpuMesh& scene, const SpotLightSetup& light) {
    DeferredEffects& fx = deferredEffects(device);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::Default;
    device.RasterizerState = RasterizerState::CullCounterClockwise;
    device.SetRenderTarget(shadowMap);
    device.Clear(Color::Transparent);
    fx.DepthWriter.Parameters["View"].SetValue(light.View);
    fx.DepthWriter.Parameters["Projection"].SetValue(light.Projection);
    fx.DepthWriter.Parameters["LightPosition"].SetValue(light.Position);
    fx.DepthWriter.Parameters["DepthPrecision"].SetValue(light.FarPlane);
    fx.DepthWriter.Parameters["World"].SetValue(Matrix::Identity);
    fx.DepthWriter.CurrentTechnique->Passes[0].Apply();
    drawMesh(device, scene);
}

void drawPointShadowMap(GraphicsDevice& device, RenderTargetCube& shadowMap, const GpuMesh& scene,
                        const PointLightSetup& light) {
    DeferredEffects& fx = deferredEffects(device);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::Default;
    device.RasterizerState = RasterizerState::CullCounterClockwise;
    fx.DepthWriter.Parameters["Projection"].SetValue(light.FaceProjection());
    fx.DepthWriter.Parameters["LightPosition"].SetValue(light.Position);
    fx.DepthWriter.Parameters["DepthPrecision"].SetValue(light.Radius);
    // The demo's order: Forward (+Z), Backward (-Z), Left (-X), Right (+X), Down (-Y), Up (+Y).
    for (CubeMapFace face : {CubeMapFace::PositiveZ, CubeMapFace::NegativeZ, CubeMapFace::NegativeX, CubeMapFace::PositiveX,
                             CubeMapFace::NegativeY, CubeMapFace::PositiveY}) {
        device.SetRenderTarget(shadowMap, face);
        device.Clear(Color::Transparent);
        fx.DepthWriter.Parameters["View"].SetValue(light.FaceView(face));
        fx.DepthWriter.Parameters["World"].SetValue(Matrix::Identity);
        fx.DepthWriter.CurrentTechnique->Passes[0].Apply();
        drawMesh(device, scene);
    }
}

void beginLightMap(GraphicsDevice& device, RenderTarget2D& lightMap, Texture& gbuffer0, Texture& gbuffer1, Texture& gbuffer2) {
    device.SetRenderTarget(lightMap);
    device.Clear(Color::Transparent);
    device.BlendState = lightMapBlendState();
    device.DepthStencilState = DepthStencilState::DepthRead;
    device.Textures[0] = &gbuffer0;
    device.SamplerStates[0] = SamplerState::LinearClamp;
    device.Textures[1] = &gbuffer1;
    device.SamplerStates[1] = SamplerState::LinearClamp;
    device.Textures[2] = &gbuffer2;
    device.SamplerStates[2] = SamplerState::PointClamp;
    device.SamplerStates[3] = SamplerState::LinearClamp;
    device.SamplerStates[4] = SamplerState::PointClamp;
}

void drawDirectionalLight(GraphicsDevice& device, const TestCamera& camera, const DirectionalLightSetup& light,
                          Vector2 gbufferTextureSize) {
    DeferredEffects& fx = deferredEffects(device);
    Matrix inverseView = Matrix::Invert(camera.View);
    Matrix inverseViewProjection = Matrix::Invert(camera.View * camera.Projection);
    Effect& e = fx.DirectionalLight;
    e.Parameters["InverseViewProjection"].SetValue(inverseViewProjection);
    e.Parameters["inverseView"].SetValue(inverseView);
    e.Parameters["CameraPosition"].SetValue(camera.Position);
    e.Parameters["GBufferTextureSize"].SetValue(gbufferTextureSize);
    FullscreenQuad fsq(device);
    fsq.ReadyBuffers(device);
    e.Parameters["L"].SetValue(Vector3::Normalize(light.Direction));
    e.Parameters["LightColor"].SetValue(light.Color);
    e.Parameters["LightIntensity"].SetValue(light.Intensity);
    e.CurrentTechnique->Passes[0].Apply();
    fsq.JustDraw(device);
}

void drawSpotLight(GraphicsDevice& device, const TestCamera& camera, const SpotLightSetup& light, Texture2D& cookie,
                   Texture2D& shadowMap, const GpuMesh& cone, Vector2 gbufferTextureSize) {
    DeferredEffects& fx = deferredEffects(device);
    Effect& e = fx.SpotLight;
    e.Parameters["View"].SetValue(camera.View);
    e.Parameters["inverseView"].SetValue(Matrix::Invert(camera.View));
    e.Parameters["Projection"].SetValue(camera.Projection);
    e.Parameters["InverseViewProjection"].SetValue(Matrix::Invert(camera.View * camera.Projection));
    e.Parameters["CameraPosition"].SetValue(camera.Position);
    e.Parameters["GBufferTextureSize"].SetValue(gbufferTextureSize);
    device.Textures[3] = &cookie;
    device.Textures[4] = &shadowMap;
    e.Parameters["World"].SetValue(light.World);
    e.Parameters["LightViewProjection"].SetValue(light.View * light.Projection);
    e.Parameters["LightPosition"].SetValue(light.Position);
    e.Parameters["LightColor"].SetValue(light.Color);
    e.Parameters["LightIntensity"].SetValue(light.Intensity);
    e.Parameters["S"].SetValue(light.Direction);
    e.Parameters["LightAngleCos"].SetValue(light.LightAngleCos());
    e.Parameters["LightHeight"].SetValue(light.FarPlane);
    e.Parameters["Shadows"].SetValue(light.Shadows);
    e.Parameters["shadowMapSize"].SetValue(light.ShadowMapResolution);
    e.Parameters["DepthPrecision"].SetValue(light.FarPlane);
    e.Parameters["DepthBias"].SetValue(light.DepthBias);
    Vector3 L = camera.Position - light.Position;
    float SL = std::fabs(Vector3::Dot(L, light.Direction));
    if (SL < light.LightAngleCos()) device.RasterizerState = RasterizerState::CullCounterClockwise;
    else device.RasterizerState = RasterizerState::CullClockwise;
    e.CurrentTechnique->Passes[0].Apply();
    drawMesh(device, cone);
}

void drawPointLight(GraphicsDevice& device, const TestCamera& camera, const PointLightSetup& light,
                    TextureCube& shadowMap, const GpuMesh& sphere, Vector2 gbufferTextureSize) {
    DeferredEffects& fx = deferredEffects(device);
    Effect& e = fx.PointLight;
    e.Parameters["inverseView"].SetValue(Matrix::Invert(camera.View));
    e.Parameters["View"].SetValue(camera.View);
    e.Parameters["Projection"].SetValue(camera.Projection);
    e.Parameters["InverseViewProjection"].SetValue(Matrix::Invert(camera.View * camera.Projection));
    e.Parameters["CameraPosition"].SetValue(camera.Position);
    e.Parameters["GBufferTextureSize"].SetValue(gbufferTextureSize);
    device.Textures[4] = &shadowMap;
    device.SamplerStates[4] = SamplerState::PointWrap;
    e.Parameters["World"].SetValue(light.World());
    e.Parameters["LightPosition"].SetValue(light.Position);
    e.Parameters["LightRadius"].SetValue(light.Radius);
    e.Parameters["LightColor"].SetValue(light.Color);
    e.Parameters["LightIntensity"].SetValue(light.Intensity);
    e.Parameters["Shadows"].SetValue(light.Shadows);
    e.Parameters["DepthPrecision"].SetValue(light.Radius);
    e.Parameters["DepthBias"].SetValue(light.DepthBias());
    e.Parameters["shadowMapSize"].SetValue(light.ShadowMapResolution);
    Vector3 diff = camera.Position - light.Position;
    float CameraToLight = float(std::sqrt(float(Vector3::Dot(diff, diff)))) / 100.0f;
    if (CameraToLight <= light.Radius) device.RasterizerState = RasterizerState::CullClockwise;
    else if (CameraToLight > light.Radius) device.RasterizerState = RasterizerState::CullCounterClockwise;
    e.CurrentTechnique->Passes[0].Apply();
    drawMesh(device, sphere);
}

void endLightMap(GraphicsDevice& device) {
    device.BlendState = BlendState::Opaque;
    device.RasterizerState = RasterizerState::CullCounterClockwise;
    device.DepthStencilState = DepthStencilState::Default;
}

void composeScene(GraphicsDevice& device, RenderTarget2D& output, Texture& gbuffer0, Texture& lightMap,
                  Vector2 gbufferTextureSize) {
    DeferredEffects& fx = deferredEffects(device);
    device.SetRenderTarget(output);
    device.Clear(Color::Transparent);
    device.Textures[0] = &gbuffer0;
    device.SamplerStates[0] = SamplerState::LinearClamp;
    device.Textures[1] = &lightMap;
    device.SamplerStates[1] = SamplerState::LinearClamp;
    fx.Compose.Parameters["GBufferTextureSize"].SetValue(gbufferTextureSize);
    fx.Compose.CurrentTechnique->Passes[0].Apply();
    FullscreenQuad fsq(device);
    fsq.Draw(device);
}

void renderSsao(GraphicsDevice& device, RenderTarget2D& target, Texture& gbuffer1, Texture& gbuffer2,
                Texture2D& randomNormals, const TestCamera& camera, float sampleRadius, float distanceScale) {
    DeferredEffects& fx = deferredEffects(device);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::Default;
    device.RasterizerState = RasterizerState::CullCounterClockwise;
    device.SetRenderTarget(target);
    device.Clear(Color::White);
    device.Textures[1] = &gbuffer1;
    device.SamplerStates[1] = SamplerState::LinearClamp;
    device.Textures[2] = &gbuffer2;
    device.SamplerStates[2] = SamplerState::PointClamp;
    device.Textures[3] = &randomNormals;
    device.SamplerStates[3] = SamplerState::LinearWrap;
    Vector3 cornerFrustum = Vector3::Zero;
    cornerFrustum.Y = float(std::tan(double(camera.FieldOfView) / 2.0)) * camera.FarPlane;
    cornerFrustum.X = cornerFrustum.Y * camera.AspectRatio;
    cornerFrustum.Z = camera.FarPlane;
    Effect& e = fx.Ssao;
    e.Parameters["Projection"].SetValue(camera.Projection);
    e.Parameters["cornerFustrum"].SetValue(cornerFrustum);
    e.Parameters["sampleRadius"].SetValue(sampleRadius);
    e.Parameters["distanceScale"].SetValue(distanceScale);
    e.Parameters["GBufferTextureSize"].SetValue(Vector2(float(target.Width()), float(target.Height())));
    e.CurrentTechnique->Passes[0].Apply();
    FullscreenQuad fsq(device);
    fsq.Draw(device);
}

void blurSsao(GraphicsDevice& device, RenderTarget2D& blurTarget, Texture& ssao, int ssaoWidth, int ssaoHeight) {
    DeferredEffects& fx = deferredEffects(device);
    device.SetRenderTarget(blurTarget);
    device.Clear(Color::White);
    device.Textures[3] = &ssao;
    device.SamplerStates[3] = SamplerState::LinearClamp;
    fx.SsaoBlur.Parameters["blurDirection"].SetValue(Vector2(1.0f / float(ssaoWidth), 1.0f / float(ssaoHeight)));
    fx.SsaoBlur.Parameters["targetSize"].SetValue(Vector2(float(ssaoWidth), float(ssaoHeight)));
    fx.SsaoBlur.CurrentTechnique->Passes[0].Apply();
    FullscreenQuad fsq(device);
    fsq.Draw(device);
}

void composeSsao(GraphicsDevice& device, RenderTarget2D& output, Texture& scene, Texture& blurred, int ssaoWidth, int ssaoHeight) {
    DeferredEffects& fx = deferredEffects(device);
    device.SetRenderTarget(output);
    device.Clear(Color::White);
    device.Textures[0] = &scene;
    device.SamplerStates[0] = SamplerState::LinearClamp;
    device.Textures[1] = &blurred;
    device.SamplerStates[1] = SamplerState::LinearClamp;
    fx.SsaoFinal.Parameters["halfPixel"].SetValue(Vector2(1.0f / float(ssaoWidth), 1.0f / float(ssaoHeight)));
    fx.SsaoFinal.CurrentTechnique->Passes[0].Apply();
    FullscreenQuad fsq(device);
    fsq.Draw(device);
}

void resetDevice(GraphicsDevice& device) {
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    for (int i = 0; i < kMaxTextureSlots; ++i) device.Textures[i] = nullptr;
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::Default;
    device.RasterizerState = RasterizerState::CullCounterClockwise;
}

}  // namespace fxport::render_test
