// The fixed inputs of the render tests: camera and lights set up as the demo sets them up
// (demo/deferred/Lights/*.cpp, Cameras/base_camera.cpp: same matrices, same derived values), the
// scene and light-volume meshes, and deterministic synthetic textures in the demo's formats
// (materials, G-buffer, light map, shadow maps, cookie, random normals, SSAO images) chosen so that
// each pass's branches are exercised.
#pragma once

#include "reference/d3d9_sampling.h"
#include "fxport/graphics.h"
#include "reference/scene_geometry.h"

namespace fxport::render_test {

// The CPU references (V4, Range4, Eval, the deferred passes ...) are reference/'s, used here unqualified.
using namespace fxport::reference;

// The render tests' target size (the G-buffer, light map, SSAO and output targets).
inline constexpr int kWidth = 96;
inline constexpr int kHeight = 64;

// BaseCamera: perspective, FieldOfView pi/4, near 0.1, far 1000, aspect of the target.
struct TestCamera {
    Vector3 Position, Target;
    float FieldOfView = MathHelper::PiOver4, AspectRatio = 1, NearPlane = 0.1f, FarPlane = 1000.0f;
    Matrix View, Projection;
};
TestCamera makeCamera(Vector3 position, Vector3 target, int width, int height);

struct DirectionalLightSetup {
    Vector3 Direction;
    Vector4 Color;
    float Intensity;
};

// Lights.SpotLight: FOV pi/2, near 1, far 100, depth bias 1/2000; View/World from Update().
struct SpotLightSetup {
    Vector3 Position, Direction;  // Direction normalised (setDirection)
    Vector4 Color;
    float Intensity = 0;
    bool Shadows = false;
    int ShadowMapResolution = 0;
    float NearPlane = 1, FarPlane = 100, FOV = MathHelper::PiOver2, DepthBias = 1.0f / 2000.0f;
    Matrix View, Projection, World;
    float LightAngleCos() const;
};
SpotLightSetup makeSpotLight(Vector3 position, Vector3 direction, Vector4 color, float intensity, bool shadows,
                             int shadowMapResolution);

// Lights.PointLight: World = Scale(radius / 100) * Translation, depth bias 1 / (20 radius).
struct PointLightSetup {
    Vector3 Position;
    float Radius = 0;
    Vector4 Color;
    float Intensity = 0;
    bool Shadows = false;
    int ShadowMapResolution = 0;
    Matrix World() const;
    float DepthBias() const { return 1.0f / (20 * Radius); }
    // LightManager.DrawShadowMap's six views (XNA face order) and projection.
    Matrix FaceView(CubeMapFace face) const;
    Matrix FaceProjection() const;
};

// Meshes, rounded to float (what the vertex buffers hold).
Mesh testSceneMesh();
Mesh pointLightGeometry();  // sphere, radius 100
Mesh spotLightGeometry();   // cone, apex at the origin, axis -Z, length 1, base radius 0.5

// Material textures for GBuffer.fx (SurfaceFormat.Color, 16x16, tiling).
struct Materials {
    CpuTexture albedo, normal, specular;
};
Materials makeMaterials();

// A plausible G-buffer of the scene seen by `camera`, as GBuffer.fx lays it out (Rgba64 albedo +
// specular intensity, Rgba64 encoded view-space normal + specular power / 255, Vector2 NDC depth +
// view z; background as Clear.fx leaves it), with pseudo-random albedo, specular values and normal
// perturbations (mostly small, some large, so that SSAOBlur's 0.99 test goes both ways).
struct GBufferImages {
    CpuTexture albedo, normals, depth;
};
GBufferImages makeSyntheticGBuffer(const Mesh& scene, const TestCamera& camera, int width, int height);

// Exponential shadow maps of the scene as DepthWriter.fx would fill them (exp(depth / 2) of the
// distance to the first front face at each texel's centre, 0 where nothing is hit).
CpuTexture makeSpotShadowMap(const Mesh& scene, const SpotLightSetup& light);
// The cube map as PointLight.fx reads it: the texel at lookup direction l holds the world direction
// (l.x, l.y, -l.z) (PointLight.fx looks up float3(-L.xy, L.z)).
CpuCube makePointShadowCube(const Mesh& scene, const PointLightSetup& light);

CpuTexture makeSpotCookie(int size);     // Color: round spot with a ring and an asymmetric notch
CpuTexture makeRandomNormals(int size);  // Color: random unit vectors encoded n * 0.5 + 0.5
// Color images for the passes that read 8-bit targets.
CpuTexture makeLightMapImage(int width, int height);
CpuTexture makeSsaoImage(int width, int height);
CpuTexture makeSceneImage(int width, int height);

}  // namespace fxport::render_test
