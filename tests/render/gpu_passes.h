// The demo's passes on the runtime, written the way demo/deferred does them (DeferredRenderer,
// LightManager, SSAO): the same effects from hlsl/xna-deferred, the same parameter values and
// names, device states, sampler states and texture slots, the same draws -- with the tests' meshes
// drawn through DrawUserIndexedPrimitives instead of Model parts.
#pragma once

#include <vector>

#include "deferred_scene.h"
#include "fxport/graphics.h"

namespace fxport::render_test {

// The ten effects, compiled once per process.
struct DeferredEffects {
    explicit DeferredEffects(GraphicsDevice& device);
    Effect Clear, GBuffer, DepthWriter, DirectionalLight, SpotLight, PointLight, Compose, Ssao, SsaoBlur, SsaoFinal;
};
DeferredEffects& deferredEffects(GraphicsDevice& device);

// POSITION0, NORMAL0, TEXCOORD0, TANGENT0, BINORMAL0 (GBuffer.fx's VSI).
struct SceneVertex {
    Vector3 Position, Normal;
    Vector2 TextureCoordinate;
    Vector3 Tangent, Binormal;
    static const fxport::VertexDeclaration VertexDeclaration;
};
struct GpuMesh {
    std::vector<SceneVertex> vertices;
    std::vector<int> indices;
};
GpuMesh toGpu(const Mesh& mesh);
void drawMesh(GraphicsDevice& device, const GpuMesh& mesh);

// DeferredRenderer.ClearGBuffer (DepthRead, Clear.fx over the three targets).
void clearGBuffer(GraphicsDevice& device, const std::vector<RenderTargetBinding>& gbuffer);
// DeferredRenderer.MakeGBuffer for one mesh with World = world.
void makeGBuffer(GraphicsDevice& device, const GpuMesh& scene, const Matrix& world, const TestCamera& camera,
                 Texture2D& albedo, Texture2D& normalMap, Texture2D& specularMap);
// LightManager.DrawShadowMaps: the spot light's map, the point light's six faces.
void drawSpotShadowMap(GraphicsDevice& device, RenderTarget2D& shadowMap, const GpuMesh& scene, const SpotLightSetup& light);
void drawPointShadowMap(GraphicsDevice& device, RenderTargetCube& shadowMap, const GpuMesh& scene,
                        const PointLightSetup& light);

// DeferredRenderer.MakeLightMap, split per light: the target, states and G-buffer samplers...
void beginLightMap(GraphicsDevice& device, RenderTarget2D& lightMap, Texture& gbuffer0, Texture& gbuffer1, Texture& gbuffer2);
// ...each light with its globals and per-light parameters...
void drawDirectionalLight(GraphicsDevice& device, const TestCamera& camera, const DirectionalLightSetup& light,
                          Vector2 gbufferTextureSize);
void drawSpotLight(GraphicsDevice& device, const TestCamera& camera, const SpotLightSetup& light, Texture2D& cookie,
                   Texture2D& shadowMap, const GpuMesh& cone, Vector2 gbufferTextureSize);
void drawPointLight(GraphicsDevice& device, const TestCamera& camera, const PointLightSetup& light,
                    TextureCube& shadowMap, const GpuMesh& sphere, Vector2 gbufferTextureSize);
// ...and the states it leaves.
void endLightMap(GraphicsDevice& device);
// DeferredRenderer.MakeFinal.
void composeScene(GraphicsDevice& device, RenderTarget2D& output, Texture& gbuffer0, Texture& lightMap,
                  Vector2 gbufferTextureSize);

// SSAO.RenderSSAO, BlurSSAO (Textures[1] = GBuffer 1 as RenderSSAO left it), Compose.
void renderSsao(GraphicsDevice& device, RenderTarget2D& target, Texture& gbuffer1, Texture& gbuffer2,
                Texture2D& randomNormals, const TestCamera& camera, float sampleRadius, float distanceScale);
void blurSsao(GraphicsDevice& device, RenderTarget2D& blurTarget, Texture& ssao, int ssaoWidth, int ssaoHeight);
void composeSsao(GraphicsDevice& device, RenderTarget2D& output, Texture& scene, Texture& blurred, int ssaoWidth, int ssaoHeight);

// Unbinds every target and texture slot (between tests).
void resetDevice(GraphicsDevice& device);

}  // namespace fxport::render_test
