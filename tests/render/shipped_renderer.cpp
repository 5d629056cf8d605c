#include "shipped_renderer.h"

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "render_harness.h"

namespace fxport::render_test {

FixedCamera::FixedCamera(const TestCamera& c) {
    Position = c.Position;
    View = c.View;
    Projection = c.Projection;
    FieldOfView = c.FieldOfView;
    AspectRatio = c.AspectRatio;
    NearPlane = c.NearPlane;
    FarPlane = c.FarPlane;
}

ShippedRenderer::ShippedRenderer(GraphicsDevice& device) {
    content.setGraphicsDevice(&device);
    content.RootDirectory = FXPORT_CONTENT_DIR;
    content.EffectDirectory = std::string(FXPORT_HLSL_DIR) + "/xna-deferred";
    renderer = std::make_unique<TheCansinDeferredRenderer::DeferredRenderer>(device, content, kWidth, kHeight);
    renderer->frustumCulling = false;  // the seed's behaviour: every light drawn
    ssao = std::make_unique<TheCansinDeferredRenderer::SSAO>(device, content, kWidth, kHeight);
}

RenderTarget2D& ShippedRenderer::gbuffer(int i) const {
    return *static_cast<RenderTarget2D*>(renderer->getGBuffer()[std::size_t(i)].RenderTarget);
}

Mesh ShippedRenderer::lightVolume(const char* asset) {
    const ModelMeshPart& part = content.Load<Model>(asset)->Meshes[0].MeshParts[0];
    std::vector<ModelVertex> vertices(std::size_t(part.VertexBuffer->VertexCount()));
    part.VertexBuffer->GetData(vertices.data(), vertices.size());
    const std::vector<std::uint32_t> indices = part.IndexBuffer->GetIndices();
    Mesh mesh;
    for (const ModelVertex& v : vertices) {
        MeshVertex m;
        m.position = {double(v.Position.X), double(v.Position.Y), double(v.Position.Z)};
        mesh.vertices.push_back(m);
    }
    for (int k = 0; k < part.PrimitiveCount; ++k) {
        std::array<int, 3> t;
        for (int c = 0; c < 3; ++c) t[std::size_t(c)] = part.VertexOffset + int(indices[std::size_t(part.StartIndex + 3 * k + c)]);
        mesh.triangles.push_back(t);
    }
    return mesh;
}

CpuTexture ShippedRenderer::randomNormals() {
    const Texture2D& texture = *content.Load<Texture2D>("RandomNormals");
    // The references sample level 0 only.
    if (texture.LevelCount() != 1) throw std::runtime_error("RandomNormals has mip levels the SSAO reference does not model");
    return readBack(texture);
}

std::unique_ptr<Model> toModel(GraphicsDevice& device, const Mesh& mesh, const ModelMaterialTextures& textures) {
    auto v3 = [](V3 v) { return Vector3(float(v.x), float(v.y), float(v.z)); };
    std::vector<ModelVertex> vertices;
    for (const MeshVertex& v : mesh.vertices)
        vertices.push_back({v3(v.position), v3(v.normal), Vector2(float(v.uv.x), float(v.uv.y)), v3(v.tangent), v3(v.binormal)});
    std::vector<std::uint32_t> indices;
    for (const auto& t : mesh.triangles)
        for (int i : t) indices.push_back(std::uint32_t(i));
    return Model::FromVertices(device, "render test scene", vertices, indices, textures);
}

void resetDevice(GraphicsDevice& device) {
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    for (int i = 0; i < kMaxTextureSlots; ++i) device.Textures[i] = nullptr;
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::Default;
    device.RasterizerState = RasterizerState::CullCounterClockwise;
}

ShippedRenderer& shippedRenderer(GraphicsDevice& device) {
    static std::unique_ptr<ShippedRenderer> shipped = std::make_unique<ShippedRenderer>(device);
    return *shipped;
}

}  // namespace fxport::render_test
