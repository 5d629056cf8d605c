#include "stability/gbuffer_pass.h"

#include "stability/case_support.h"

namespace fxport::stability {

namespace {

// GBuffer.fx's vertex input: POSITION0, NORMAL0, TEXCOORD0, TANGENT0, BINORMAL0.
struct MeshVertex {
    Vector3 position, normal;
    Vector2 uv;
    Vector3 tangent, binormal;
};

const VertexDeclaration& meshDeclaration() {
    static const VertexDeclaration declaration(
        int(sizeof(MeshVertex)),
        {VertexElement(0, VertexElementFormat::Vector3, VertexElementUsage::Position, 0),
         VertexElement(12, VertexElementFormat::Vector3, VertexElementUsage::Normal, 0),
         VertexElement(24, VertexElementFormat::Vector2, VertexElementUsage::TextureCoordinate, 0),
         VertexElement(32, VertexElementFormat::Vector3, VertexElementUsage::Tangent, 0),
         VertexElement(44, VertexElementFormat::Vector3, VertexElementUsage::Binormal, 0)});
    return declaration;
}

std::unique_ptr<Texture2D> oneTexel(GraphicsDevice& device, Vector4 value) {
    auto t = std::make_unique<Texture2D>(device, 1, 1, false, SurfaceFormat::Vector4);
    t->SetData(std::vector<Vector4>{value});
    return t;
}

}  // namespace

GBufferTargets drawGBufferQuad(GraphicsDevice& device, Effect& gbuffer, const GBufferQuad& q, int size, CaseResult& r) {
    GBufferTargets t;
    t.albedo = std::make_unique<RenderTarget2D>(device, size, size, false, SurfaceFormat::Vector4, DepthFormat::None);
    t.normals = std::make_unique<RenderTarget2D>(device, size, size, false, q.normalFormat, DepthFormat::None);
    t.depth = std::make_unique<RenderTarget2D>(device, size, size, false, SurfaceFormat::Vector2, DepthFormat::None);
    t.albedo->Name = "GBuffer0 (Vector4)";
    t.normals->Name = std::string("GBuffer1 (") + surfaceFormatName(q.normalFormat) + ")";
    t.depth->Name = "GBuffer2 (Vector2)";
    auto white = oneTexel(device, Vector4(1, 1, 1, 1));
    auto flatNormal = oneTexel(device, Vector4(0.5f, 0.5f, 1, 1));
    auto specular = oneTexel(device, Vector4(q.specularIntensity, q.specularPower, 0, 1));

    FiniteCheck check(device);
    check.beginPass("GBuffer");
    device.SetRenderTargets({RenderTargetBinding(t.albedo.get()), RenderTargetBinding(t.normals.get()),
                             RenderTargetBinding(t.depth.get())});
    device.Clear(Color::TransparentBlack);
    device.BlendState = BlendState::Opaque;
    device.DepthStencilState = DepthStencilState::None;
    device.RasterizerState = RasterizerState::CullNone;
    gbuffer.Parameters["World"].SetValue(Matrix::Identity);
    gbuffer.Parameters["View"].SetValue(Matrix::Identity);
    gbuffer.Parameters["Projection"].SetValue(q.projection);
    gbuffer.Parameters["WorldViewIT"].SetValue(Matrix::Identity);  // Transpose(Invert(World * View))
    gbuffer.Parameters["Texture"].SetValue(*white);
    gbuffer.Parameters["NormalMap"].SetValue(*flatNormal);
    gbuffer.Parameters["SpecularMap"].SetValue(*specular);
    gbuffer.CurrentTechnique->Passes[0].Apply();
    const float h = float(q.halfExtent), z = -float(q.distance);
    auto corner = [&](float x, float y, float u, float v) {
        return MeshVertex{Vector3(x, y, z), q.normal, Vector2(u, v), q.tangent, q.binormal};
    };
    const MeshVertex v[6] = {corner(-h, h, 0, 0),   corner(h, h, 1, 0), corner(-h, -h, 0, 1),
                             corner(-h, -h, 0, 1), corner(h, h, 1, 0), corner(h, -h, 1, 1)};
    device.DrawUserPrimitives(PrimitiveType::TriangleList, v, 0, 2, meshDeclaration());
    device.SetRenderTarget(nullptr);
    takeFindings(check.endPass(), r);
    return t;
}

}  // namespace fxport::stability
