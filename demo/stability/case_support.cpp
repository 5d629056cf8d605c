#include "stability/case_support.h"

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
    VertexPositionTexture v[6] = {{Vector3(-1, 1, 0.5f), Vector2(0, 0)},  {Vector3(1, 1, 0.5f), Vector2(1, 0)},
                                  {Vector3(-1, -1, 0.5f), Vector2(0, 1)}, {Vector3(-1, -1, 0.5f), Vector2(0, 1)},
                                  {Vector3(1, 1, 0.5f), Vector2(1, 0)},   {Vector3(1, -1, 0.5f), Vector2(1, 1)}};
    device.DrawUserPrimitives(PrimitiveType::TriangleList, v, 0, 2);
    device.SetRenderTarget(nullptr);
    for (int slot = 0; slot < 5; ++slot) device.Textures[slot] = nullptr;
    takeFindings(check.endPass(), r);
}

std::vector<Vector4> readBack(RenderTarget2D& target) { return target.GetDataAsVector4(); }

}  // namespace fxport::stability
