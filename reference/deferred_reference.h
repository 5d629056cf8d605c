// CPU references of the deferred demo's passes (hlsl/xna-deferred/*.fx), in double precision,
// written from the HLSL as the tutorial has it -- its quirks included: the G-buffer read one texel
// up-left of the pixel (UV - 1/GBufferTextureSize), manualSample's texelSize = 1/textureSize.x for
// both axes, DirectionalLight's Position.y = -(UV.x * 2 - 1), SSAO's unflipped v, the truncations
// mul(float3, float4x4) -> upper-left 3x3 and float4 -> float (.x).
//
// Each function computes one pixel of one target for an Eval (reference_eval.h): D3D9 sampling
// through d3d9_sampling.h, geometry through the candidates of scene_geometry.h. Parameters are the
// values handed to the effect (float matrices converted to double), so the GPU and the reference
// start from the same numbers.
#pragma once

#include <vector>

#include "reference/d3d9_sampling.h"
#include "reference/reference_eval.h"
#include "reference/scene_geometry.h"

namespace fxport::reference {

struct PixelPos {
    int x, y, width, height;
};

// A full-screen quad's varyings at the pixel (FullscreenQuad: UV (0,0) at NDC (-1,+1)):
// UV = (x / W, (y + 1/256) / H) (scene_geometry.h: kPixelBiasX, kPixelBiasY) and the unshifted NDC position.
V2 fullscreenUV(PixelPos p);
V2 fullscreenNdc(PixelPos p);

// ---- Clear.fx: three constant targets.
Range4 clearPixel(int target);

// ---- GBuffer.fx
struct GBufferPass {
    const Mesh* mesh = nullptr;
    WorldMesh worldMesh;  // the mesh under World, for visibility
    View3D camera;
    M4 world, view, projection, worldViewIT;
    const CpuTexture *albedoMap = nullptr, *normalMap = nullptr, *specularMap = nullptr;
};
// target 0 = Albedo (COLOR0), 1 = Normals, 2 = Depth. `visible` = visibleCandidates() of the pixel.
Range4 gbufferPixel(Eval& ev, const GBufferPass& pass, const std::vector<int>& visible, PixelPos p, int target);

// ---- DepthWriter.fx (spot shadow map, or one cube face of the point light's)
struct DepthWriterPass {
    const Mesh* mesh = nullptr;
    WorldMesh worldMesh;
    View3D lightView;  // View, Projection as set on the effect
    M4 world;
    V3 lightPosition;
    double depthPrecision = 0;
};
Range4 depthWriterPixel(Eval& ev, const DepthWriterPass& pass, const std::vector<int>& visible, PixelPos p);

// The G-buffer as the light passes sample it (s0 albedo/specular, s1 normals/power, s2 depth).
struct GBufferTextures {
    const CpuTexture *albedo = nullptr, *normals = nullptr, *depth = nullptr;
};

// ---- DirectionalLight.fx (full-screen quad)
struct DirectionalLightParams {
    M4 inverseViewProjection, inverseView;
    V3 cameraPosition, L;
    V4 lightColor;
    double lightIntensity = 0;
    V2 gbufferTextureSize;
};
Range4 directionalLightPixel(Eval& ev, const GBufferTextures& gb, const DirectionalLightParams& q, PixelPos p);

// ---- SpotLight.fx (cone volume)
struct SpotLightParams {
    M4 inverseView, inverseViewProjection, lightViewProjection;
    V3 cameraPosition, lightPosition, S;
    V4 lightColor;
    double lightIntensity = 0, lightAngleCos = 0, lightHeight = 0;
    V2 gbufferTextureSize;
    bool shadows = false;
    double shadowMapSize = 0, depthPrecision = 0, depthBias = 0;
};
// `coverage` = coverageCandidates() of the cone at the pixel (how many fragments it gets).
Range4 spotLightPixel(Eval& ev, const GBufferTextures& gb, const CpuTexture& cookie, const CpuTexture& shadowMap,
                      const SpotLightParams& q, const std::vector<int>& coverage, PixelPos p);

// ---- PointLight.fx (sphere volume)
struct PointLightParams {
    M4 inverseView, inverseViewProjection;
    V3 cameraPosition, lightPosition;
    double lightRadius = 0;
    V4 lightColor;
    double lightIntensity = 0;
    V2 gbufferTextureSize;
    bool shadows = false;
    double depthPrecision = 0, depthBias = 0, shadowMapSize = 0;
};
Range4 pointLightPixel(Eval& ev, const GBufferTextures& gb, const CpuCube& shadowMap, const PointLightParams& q,
                       const std::vector<int>& coverage, PixelPos p);

// ---- Composition.fx
Range4 compositionPixel(Eval& ev, const CpuTexture& albedo, const CpuTexture& lightMap, V2 gbufferTextureSize, PixelPos p);

// ---- SSAO.fx
struct SsaoParams {
    M4 projection;
    V3 cornerFustrum;
    double sampleRadius = 0, distanceScale = 0;
    V2 gbufferTextureSize;
};
Range4 ssaoPixel(Eval& ev, const CpuTexture& normals, const CpuTexture& depth, const CpuTexture& randomNormals,
                 const SsaoParams& q, PixelPos p);

// ---- SSAOBlur.fx
Range4 ssaoBlurPixel(Eval& ev, const CpuTexture& normals, const CpuTexture& ssao, V2 blurDirection, V2 targetSize,
                     PixelPos p);

// ---- SSAOFinal.fx
Range4 ssaoFinalPixel(Eval& ev, const CpuTexture& scene, const CpuTexture& ssao, V2 halfPixel, PixelPos p);

}  // namespace fxport::reference
