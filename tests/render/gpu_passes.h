// The two passes of the deferred demo that the render tests cannot run in the shipped code, because
// they draw the tests' own scene mesh and the shipped code draws only glTF Models: MakeGBuffer and
// LightManager.DrawShadowMaps (and RenderSSAO for the end-to-end test, see below), written the way demo/deferred does them (same effects, parameters,
// states and draws), with the mesh drawn through DrawUserIndexedPrimitives instead of Model parts.
// Every other pass is the shipped DeferredRenderer's and SSAO's (shipped_renderer.h).
#pragma once

#include <vector>

#include "deferred_scene.h"
#include "fxport/graphics.h"

namespace fxport::render_test {

// The effects these passes use, compiled once per process.
struct DeferredEffects {
    explicit DeferredEffects(GraphicsDevice& device);
    Effect GBuffer, DepthWriter, Ssao;
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

// DeferredRenderer.MakeGBuffer for one mesh with World = world.
void makeGBuffer(GraphicsDevice& device, const GpuMesh& scene, const Matrix& world, const TestCamera& camera,
                 Texture2D& albedo, Texture2D& normalMap, Texture2D& specularMap);
// LightManager.DrawShadowMaps: the spot light's map, the point light's six faces.
void drawSpotShadowMap(GraphicsDevice& device, RenderTarget2D& shadowMap, const GpuMesh& scene, const SpotLightSetup& light);
void drawPointShadowMap(GraphicsDevice& device, RenderTargetCube& shadowMap, const GpuMesh& scene,
                        const PointLightSetup& light);

// SSAO.RenderSSAO with the tests' own random-normal texture, for the end-to-end test only: the
// shipped SSAO samples the content's 64x64 texture, with which one pixel of the end-to-end chain
// (reference G-buffer in, not the GPU's) leaves its derived bound (0.0248 > 0.0183: the first-order
// slack does not see a depth comparison flip). The per-pass SSAO test runs the shipped RenderSSAO.
void renderSsao(GraphicsDevice& device, RenderTarget2D& target, Texture& gbuffer1, Texture& gbuffer2,
                Texture2D& randomNormals, const TestCamera& camera, float sampleRadius, float distanceScale);

// Unbinds every target and texture slot (between tests).
void resetDevice(GraphicsDevice& device);

}  // namespace fxport::render_test
