// DeferredRenderer (seed 001, Catalin Zima's deferred rendering series, chapter "Point Lights"):
// the G-buffer (colorRT, normalRT, depthRT), the light map (lightRT) with one directional light and
// the chapter's 22 animated point lights drawn as sphere volumes, and the final combine.
// The members and methods the chapter adds (pointLightEffect, sphereModel, DrawPointLight, the
// DrawLights body) are from the seed; the rest of the class is the series' earlier chapters,
// reconstructed (see RECONSTRUCTED.md).
#pragma once

#include <memory>
#include <vector>

#include "pointlights/camera.h"
#include "pointlights/quad_renderer.h"
#include "pointlights/scene.h"
#include "pointlights/xna.h"

namespace DeferredLighting {

// fxport addition (not in the seed): the quality/time knobs `fxdemo report` sweeps. Chosen before
// the DeferredRenderer is made (the targets are made there); the defaults are the chapter's.
enum class GBufferFormats {
    Tutorial,  // the series' Color / Color / Single, light map Color
    Half16,    // HalfVector4 / HalfVector4 / HalfSingle, light map HalfVector4
    Float32,   // Vector4 / Vector4 / Single, light map Vector4 (GL blends 32-bit float targets)
};
struct RendererQuality {
    GBufferFormats gbufferFormats = GBufferFormats::Tutorial;
    // 0: the chapter's 22 point lights; N: N lights in the chapter's two animated rings.
    int lightCount = 0;
    // 0: PointLightGeometry (32 x 16); else a UV sphere of this many segments (rings = half).
    int sphereSegments = 0;
};

class DeferredRenderer {
public:
    using GBufferFormats = DeferredLighting::GBufferFormats;
    using Quality = RendererQuality;

private:
    Camera* camera;
    QuadRenderer* quadRenderer;
    Scene* scene;

    std::unique_ptr<RenderTarget2D> colorRT;   //color and specular intensity
    std::unique_ptr<RenderTarget2D> normalRT;  //normals + specular power
    std::unique_ptr<RenderTarget2D> depthRT;   //depth
    std::unique_ptr<RenderTarget2D> lightRT;   //lighting

    Effect* clearBufferEffect;
    Effect* directionalLightEffect;

    Effect* pointLightEffect;
    Model* sphereModel;  //point ligt volume

    Effect* finalCombineEffect;

    // The chapter's exercise (fxport, not in the seed): SpotLight.fx and the cone volume, loaded
    // the first time the spot light is drawn (a scene without it never compiles SpotLight.fx).
    Effect* spotLightEffect = nullptr;
    Model* coneModel = nullptr;  //spot light volume
    ContentManager* content = nullptr;

    Vector2 halfPixel;

public:
    DeferredRenderer(fxport::GraphicsDevice& GraphicsDevice, ContentManager& Content, Camera& camera,
                     QuadRenderer& quadRenderer, Scene& scene, const Quality& quality = Quality());
    const Quality quality;  // fxport
    void Draw(const GameTime& gameTime);

    // fxport additions: the targets for fxdemo's debug sheet, a GPU timer for the passes, and how
    // the chapter's light positions and radii are placed in our Scene (see DrawPointLight).
    RenderTarget2D& getColorRT() const { return *colorRT; }
    RenderTarget2D& getNormalRT() const { return *normalRT; }
    RenderTarget2D& getDepthRT() const { return *depthRT; }
    RenderTarget2D& getLightRT() const { return *lightRT; }
    void setGpuTimer(GpuTimer* timer) { gpuTimer = timer; }
    struct LightRig {
        float scale = 0.3f;                     // seed units -> Scene units (positions and radii)
        Vector3 center = Vector3(0, 4.0f, 0);   // where the seed's origin (its ship's centre) goes
        float sphereModelRadius = 100.0f;       // PointLightGeometry.gltf (seed's sphere.x: 1)
    };
    LightRig lightRig;
    // fxdemo --spot: also draw the chapter's exercise, one spot light sweeping over the scene.
    bool drawSpotLight = false;
    // The last frame's lights (after the light rig), for fxdemo's CPU reference check -- the culled
    // ones too, so that the reference (which lights every pixel a light reaches) catches a light
    // culled by mistake.
    struct DrawnPointLight {
        Vector3 position;
        Vector3 color;
        float radius, intensity;
        bool inside;
        bool culled;
    };
    std::vector<DrawnPointLight> drawnPointLights;
    Vector3 drawnDirection;
    Vector3 drawnDirectionalColor;
    Vector2 getHalfPixel() const { return halfPixel; }
    // Counts of the last frame's point lights drawn with each cull mode.
    int insideLights = 0, outsideLights = 0;
    bool spotInside = false;
    // fxport (issue 6): a point light whose sphere is outside the camera's frustum is not drawn
    // (frustumCulling off: every light is drawn, as in the chapter); how many the last frame left out.
    bool frustumCulling = true;
    int culledLights = 0;

private:
    void SetGBuffer();
    void ResolveGBuffer();
    void ClearGBuffer();
    void DrawDirectionalLight(Vector3 lightDirection, Color color);
    void DrawPointLight(Vector3 lightPosition, Color color, float lightRadius, float lightIntensity);
    void DrawSpotLight(Vector3 lightPosition, Vector3 spotDirection, Color color, float lightRadius,
                       float lightIntensity, float spotLightAngle, float spotDecayExponent);
    void DrawLights(const GameTime& gameTime);
    // fxport: Quality::lightCount lights in the chapter's pattern; the generated light sphere.
    void DrawManyPointLights(const GameTime& gameTime, const Color* colors);
    void DrawLightSphere();
    std::vector<VertexPositionColor> sphereVertices;
    std::vector<int> sphereIndices;

    // XNA's DrawableGameComponent.GraphicsDevice.
    fxport::GraphicsDevice& GraphicsDevice;
    GpuTimer* gpuTimer = nullptr;
    BlendState lightBlendState;
};

}  // namespace DeferredLighting
