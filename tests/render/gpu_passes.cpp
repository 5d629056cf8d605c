#include "gpu_passes.h"

#include <cmath>
#include <memory>
#include <string>

namespace fxport::render_test {

namespace {

std::string effectPath(const char* name) { return std::string(FXPORT_HLSL_DIR) + "/xna-deferred/" + name + ".fx"; }

}  // namespace

DeferredEffects::DeferredEffects(GraphicsDevice& device)
    : GBuffer(device, effectPath("GBuffer")), DepthWriter(device, effectPath("DepthWriter")), Ssao(device, effectPath("SSAO")) {
    for (Effect* e : {&GBuffer, &DepthWriter, &Ssao}) e->CurrentTechnique = e->Techniques[0];
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

void resetDevice(GraphicsDevice& device) {
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    for (int i = 0; i < kMaxTextureSlots; ++i) device.Textures[i] = nullptr;
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::Default;
    device.RasterizerState = RasterizerState::CullCounterClockwise;
}

}  // namespace fxport::render_test
