// Each pass of the deferred demo (hlsl/xna-deferred) rendered headless
// at 96x64 from fixed synthetic inputs, read back, and compared pixel by pixel with an independent
// double-precision CPU reference of the same HLSL (deferred_reference.h) evaluated on the same
// input texels under D3D9's sampling and pixel-centre rules (d3d9_sampling.h, scene_geometry.h).
// Bounds: render_harness.h; the per-pixel slack: reference_eval.h. Each test prints its max / RMS
// error ("[render] ..." lines) and records them as test properties.
//
// Every pass runs in the shipped code itself (shipped_renderer.h), one pass at a time on inputs
// uploaded into its targets: the demo's DeferredRenderer (ClearGBuffer; MakeGBuffer of the tests'
// scene as a Model; MakeLightMap with one directional, spot or point light of the demo's Lights
// classes, their shadow maps and the cookie uploaded, the volumes the content's models; MakeFinal),
// its LightManager (DrawShadowMaps of the scene Model into the lights' own maps) and SSAO (RenderSSAO
// with the content's random normals, BlurSSAO, Compose). The references take the tests' own
// matrices (deferred_scene.h), not the renderer's, wherever the pass's geometry depends on them.
#include <gtest/gtest.h>

#include <functional>
#include <memory>

#include "deferred/Lights/light_manager.h"
#include "reference/deferred_reference.h"
#include "deferred_scene.h"
#include "light_params.h"
#include "render_harness.h"
#include "runtime_test_support.h"
#include "shipped_renderer.h"

namespace fxport::render_test {
namespace {

template <class F>
std::vector<std::vector<int>> perPixel(int width, int height, F f) {
    std::vector<std::vector<int>> out;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) out.push_back(f(x, y));
    return out;
}

// Inputs shared by the tests, built once.
struct PassInputs {
    GraphicsDevice& device;
    TestCamera camera;
    Vector2 size{float(kWidth), float(kHeight)};
    Mesh scene = testSceneMesh();
    Materials materials = makeMaterials();
    Texture2D albedoMap, normalMap, specularMap;
    std::unique_ptr<Model> sceneModel;  // `scene` with the material maps, as the shipped passes draw it
    GBufferImages gbuffer;
    DirectionalLightSetup directional{Vector3(0.3f, -1.0f, -0.4f), Vector4(1.0f, 0.85f, 0.7f, 1.0f), 0.9f};
    SpotLightSetup spot = makeSpotLight(Vector3(0, 6, 0.5f), Vector3(0.15f, -1, 0.45f), Vector4(1, 0.95f, 0.8f, 1), 0.9f, true, 64);
    CpuTexture spotShadow, cookie;
    Texture2D cookieGpu;
    PointLightSetup point{Vector3(0.5f, 3, 1), 20, Vector4(0.9f, 0.95f, 1, 1), 0.8f, true, 32};
    CpuCube pointShadow;
    CpuTexture lightMap, ssao, sceneImage;

    explicit PassInputs(GraphicsDevice& d)
        : device(d), camera(makeCamera(Vector3(0, 9, 17), Vector3(0, 1.5f, 0), kWidth, kHeight)),
          albedoMap(d, 16, 16, false, SurfaceFormat::Color), normalMap(d, 16, 16, false, SurfaceFormat::Color),
          specularMap(d, 16, 16, false, SurfaceFormat::Color), gbuffer(makeSyntheticGBuffer(scene, camera, kWidth, kHeight)),
          spotShadow(makeSpotShadowMap(scene, spot)),
          cookie(makeSpotCookie(32)), cookieGpu(d, 32, 32, false, SurfaceFormat::Color),
          pointShadow(makePointShadowCube(scene, point)),
          lightMap(makeLightMapImage(kWidth, kHeight)), ssao(makeSsaoImage(kWidth, kHeight)),
          sceneImage(makeSceneImage(kWidth, kHeight)) {
        upload(albedoMap, materials.albedo);
        upload(normalMap, materials.normal);
        upload(specularMap, materials.specular);
        upload(cookieGpu, cookie);
        sceneModel = toModel(d, scene, {&albedoMap, &normalMap, &specularMap});
    }
    std::vector<Model*> models() const { return {sceneModel.get()}; }

    GBufferTextures gbufferTextures() const { return {&gbuffer.albedo, &gbuffer.normals, &gbuffer.depth}; }
    View3D cameraView() const { return makeView(toM4(camera.View), toM4(camera.Projection), kWidth, kHeight); }
};

class DeferredPasses : public ::testing::Test {
protected:
    static PassInputs& in() {
        static std::unique_ptr<PassInputs> inputs = std::make_unique<PassInputs>(test::testDevice());
        return *inputs;
    }
    static ShippedRenderer& shipped() { return shippedRenderer(test::testDevice()); }
    // The inputs' G-buffer, in the renderer's own G-buffer targets.
    static void uploadGBuffer(ShippedRenderer& r, const PassInputs& s) {
        upload(r.gbuffer(0), s.gbuffer.albedo);
        upload(r.gbuffer(1), s.gbuffer.normals);
        upload(r.gbuffer(2), s.gbuffer.depth);
    }
    void TearDown() override { resetDevice(device); }

    // Compares, reports, and fails with the first offending pixels.
    static void check(const std::string& pass, const CpuTexture& gpu, const RefImage& ref, int maxChannels = 4) {
        Comparison c = compare(pass, gpu, ref, maxChannels);
        report(c);
        EXPECT_EQ(c.failures, 0) << pass << ": " << c.failures << " of " << c.samples << " samples outside the bound\n"
                                 << c.failureText;
        // The bounds must still see a one-pixel shift wherever the image changes by more than them.
        EXPECT_GE(c.shiftedFailureFraction, 0.5 * c.shiftVisibleFraction)
            << pass << ": a one-pixel shift of the GPU image passes the bounds";
    }

    // The shipped renderer's MakeLightMap of `lights` on the inputs' G-buffer (uploaded into its
    // targets) seen by the inputs' camera; returns its light map.
    CpuTexture makeLightMap(TheCansinDeferredRenderer::Lights::LightManager& lights) {
        FixedCamera camera(in().camera);
        shipped().renderer->MakeLightMap(device, lights, camera);
        device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
        return readBack(shipped().renderer->getLightMap());
    }
    // The reference light map of one light volume: `pixel` is the light's reference for a pixel
    // given how many of the volume's fragments cover it.
    RefImage lightVolumeReference(const WorldMesh& volume, Cull cull,
                                  const std::function<Range4(Eval&, const std::vector<int>&, PixelPos)>& pixel) {
        View3D view = in().cameraView();
        std::vector<std::vector<int>> coverage =
            perPixel(kWidth, kHeight, [&](int x, int y) { return coverageCandidates(volume, view, cull, x, y); });
        return referenceImage(kWidth, kHeight, SurfaceFormat::Color, true, [&](Eval& ev, PixelPos p) {
            return pixel(ev, coverage[std::size_t(p.y * kWidth + p.x)], p);
        });
    }

    // The shipped renderer's MakeLightMap with one spot light of the demo's Lights::SpotLight, its
    // shadow map and cookie the inputs' (the volume: the content's SpotLightGeometry).
    void spotTest(const std::string& pass, bool shadows) {
        using namespace TheCansinDeferredRenderer;
        PassInputs& s = in();
        ShippedRenderer& r = shipped();
        uploadGBuffer(r, s);
        Lights::LightManager lights(r.content);
        auto owned = std::make_unique<Lights::SpotLight>(device, s.spot.Position, s.spot.Direction, s.spot.Color, s.spot.Intensity,
                                                         shadows, s.spot.ShadowMapResolution, &s.cookieGpu);
        const Lights::SpotLight& shipped = *owned;
        upload(owned->MakeShadowMap(), s.spotShadow);
        lights.AddLight(std::move(owned));
        CpuTexture gpu = makeLightMap(lights);
        ASSERT_EQ(r.renderer->getFrameStats().spotLightsDrawn, 1);

        // The reference's light: the shipped light's own matrices and values.
        SpotLightSetup light = s.spot;
        light.Shadows = shadows;
        light.View = shipped.getView();
        light.Projection = shipped.getProjection();
        light.World = shipped.getWorld();
        light.Direction = shipped.getDirection();
        WorldMesh cone = toWorld(r.lightVolume("SpotLightGeometry"), toM4(light.World));
        SpotLightParams q = spotParams(s.camera, light);
        GBufferTextures gb = s.gbufferTextures();
        check(pass, gpu, lightVolumeReference(cone, spotCull(s.camera, light), [&](Eval& ev, const std::vector<int>& coverage, PixelPos p) {
                  return spotLightPixel(ev, gb, s.cookie, s.spotShadow, q, coverage, p);
              }));
    }

    // The same with one Lights::PointLight (the volume: the content's PointLightGeometry).
    void pointTest(const std::string& pass, bool shadows) {
        using namespace TheCansinDeferredRenderer;
        PassInputs& s = in();
        ShippedRenderer& r = shipped();
        uploadGBuffer(r, s);
        Lights::LightManager lights(r.content);
        auto owned = std::make_unique<Lights::PointLight>(device, s.point.Position, s.point.Radius, s.point.Color, s.point.Intensity,
                                                          shadows, s.point.ShadowMapResolution);
        const Lights::PointLight& shipped = *owned;
        RenderTargetCube& shadowMap = owned->MakeShadowMap();
        for (int f = 0; f < 6; ++f) upload(shadowMap, CubeMapFace(f), s.pointShadow.faces[std::size_t(f)]);
        lights.AddLight(std::move(owned));
        CpuTexture gpu = makeLightMap(lights);
        ASSERT_EQ(r.renderer->getFrameStats().pointLightsDrawn, 1);

        PointLightSetup light = s.point;
        light.Shadows = shadows;
        WorldMesh sphere = toWorld(r.lightVolume("PointLightGeometry"), toM4(shipped.World()));
        PointLightParams q = pointParams(s.camera, light);
        q.depthBias = shipped.getDepthBias();
        GBufferTextures gb = s.gbufferTextures();
        check(pass, gpu, lightVolumeReference(sphere, pointCull(s.camera, light), [&](Eval& ev, const std::vector<int>& coverage, PixelPos p) {
                  return pointLightPixel(ev, gb, s.pointShadow, q, coverage, p);
              }));
    }

    GraphicsDevice& device = test::testDevice();
};

TEST_F(DeferredPasses, Clear) {
    ShippedRenderer& r = shipped();
    // Start from something else than the clear values.
    for (int t = 0; t < 3; ++t) {
        device.SetRenderTarget(&r.gbuffer(t));
        device.Clear(ClearOptions::Target | ClearOptions::DepthBuffer, Vector4(0.25f, 0.75f, 0.125f, 0.625f), 1.0f, 0);
    }
    r.renderer->ClearGBuffer(device);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    const char* names[3] = {"Clear.Albedo", "Clear.Normals", "Clear.Depth"};
    for (int t = 0; t < 3; ++t) {
        RefImage ref = referenceImage(kWidth, kHeight, r.gbuffer(t).Format(), false, [&](Eval&, PixelPos) { return clearPixel(t); });
        check(names[t], readBack(r.gbuffer(t)), ref);
    }
}

TEST_F(DeferredPasses, GBuffer) {
    PassInputs& s = in();
    ShippedRenderer& r = shipped();
    Matrix world = Matrix::Identity;  // the scene Model's one bone
    // The renderer's ClearGBuffer binds and clears its G-buffer; its MakeGBuffer draws the scene into it.
    r.renderer->ClearGBuffer(device);
    FixedCamera camera(s.camera);
    r.renderer->MakeGBuffer(device, s.models(), camera);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));

    GBufferPass pass;
    pass.mesh = &s.scene;
    pass.world = toM4(world);
    pass.worldMesh = toWorld(s.scene, pass.world);
    pass.camera = s.cameraView();
    pass.view = toM4(s.camera.View);
    pass.projection = toM4(s.camera.Projection);
    pass.worldViewIT = toM4(Matrix::Transpose(Matrix::Invert(world * s.camera.View)));
    pass.albedoMap = &s.materials.albedo;
    pass.normalMap = &s.materials.normal;
    pass.specularMap = &s.materials.specular;
    std::vector<std::vector<int>> visible = perPixel(
        kWidth, kHeight, [&](int x, int y) { return visibleCandidates(pass.worldMesh, pass.camera, Cull::CounterClockwiseFace, x, y); });
    RenderTarget2D* targets[3] = {&r.gbuffer(0), &r.gbuffer(1), &r.gbuffer(2)};
    const char* names[3] = {"GBuffer.Albedo", "GBuffer.Normals", "GBuffer.Depth"};
    for (int t = 0; t < 3; ++t) {
        RefImage ref = referenceImage(kWidth, kHeight, targets[t]->Format(), true, [&](Eval& ev, PixelPos p) {
            return gbufferPixel(ev, pass, visible[std::size_t(p.y * kWidth + p.x)], p, t);
        });
        // 8-bit material textures filtered linearly: the slack is the rule here (see d3d9_sampling.h).
        check(names[t], readBack(*targets[t]), ref);
    }
}

TEST_F(DeferredPasses, DepthWriterSpotShadowMap) {
    PassInputs& s = in();
    const SpotLightSetup& light = s.spot;
    int n = light.ShadowMapResolution;
    // The shipped LightManager draws the map of a demo SpotLight with shadows.
    TheCansinDeferredRenderer::Lights::LightManager lights(shipped().content);
    auto owned = std::make_unique<TheCansinDeferredRenderer::Lights::SpotLight>(
        device, light.Position, light.Direction, light.Color, light.Intensity, true, n, &s.cookieGpu);
    RenderTarget2D& shadowMap = owned->MakeShadowMap();
    lights.AddLight(std::move(owned));
    lights.DrawShadowMaps(device, s.models());
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    ASSERT_EQ(lights.shadowMapsDrawn, 1);

    DepthWriterPass pass;
    pass.mesh = &s.scene;
    pass.world = M4::identity();
    pass.worldMesh = toWorld(s.scene, pass.world);
    pass.lightView = makeView(toM4(light.View), toM4(light.Projection), n, n);
    pass.lightPosition = toV3(light.Position);
    pass.depthPrecision = light.FarPlane;
    std::vector<std::vector<int>> visible =
        perPixel(n, n, [&](int x, int y) { return visibleCandidates(pass.worldMesh, pass.lightView, Cull::CounterClockwiseFace, x, y); });
    RefImage ref = referenceImage(n, n, SurfaceFormat::Single, true, [&](Eval& ev, PixelPos p) {
        return depthWriterPixel(ev, pass, visible[std::size_t(p.y * n + p.x)], p);
    });
    check("DepthWriter.Spot", readBack(shadowMap), ref, 1);
}

TEST_F(DeferredPasses, DepthWriterPointCubeShadowMap) {
    PassInputs& s = in();
    const PointLightSetup& light = s.point;
    int n = light.ShadowMapResolution;
    // The shipped LightManager draws the six faces of a demo PointLight with shadows.
    TheCansinDeferredRenderer::Lights::LightManager lights(shipped().content);
    auto owned = std::make_unique<TheCansinDeferredRenderer::Lights::PointLight>(device, light.Position, light.Radius, light.Color,
                                                                                 light.Intensity, true, n);
    RenderTargetCube& shadowMap = owned->MakeShadowMap();
    lights.AddLight(std::move(owned));
    lights.DrawShadowMaps(device, s.models());
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    ASSERT_EQ(lights.shadowMapsDrawn, 1);

    const char* faceNames[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    for (int f = 0; f < 6; ++f) {
        DepthWriterPass pass;
        pass.mesh = &s.scene;
        pass.world = M4::identity();
        pass.worldMesh = toWorld(s.scene, pass.world);
        pass.lightView = makeView(toM4(light.FaceView(CubeMapFace(f))), toM4(light.FaceProjection()), n, n);
        pass.lightPosition = toV3(light.Position);
        pass.depthPrecision = light.Radius;
        std::vector<std::vector<int>> visible =
            perPixel(n, n, [&](int x, int y) { return visibleCandidates(pass.worldMesh, pass.lightView, Cull::CounterClockwiseFace, x, y); });
        RefImage ref = referenceImage(n, n, SurfaceFormat::Single, true, [&](Eval& ev, PixelPos p) {
            return depthWriterPixel(ev, pass, visible[std::size_t(p.y * n + p.x)], p);
        });
        check(std::string("DepthWriter.Cube") + faceNames[f], readBack(shadowMap, CubeMapFace(f)), ref, 1);
    }
}

TEST_F(DeferredPasses, DirectionalLight) {
    PassInputs& s = in();
    ShippedRenderer& r = shipped();
    uploadGBuffer(r, s);
    TheCansinDeferredRenderer::Lights::LightManager lights(r.content);
    lights.AddLight(std::make_unique<TheCansinDeferredRenderer::Lights::DirectionalLight>(
        s.directional.Direction, s.directional.Color, s.directional.Intensity));
    CpuTexture gpu = makeLightMap(lights);
    ASSERT_EQ(r.renderer->getFrameStats().directionalLightsDrawn, 1);

    DirectionalLightParams q = directionalParams(s.camera, s.directional);
    GBufferTextures gb = s.gbufferTextures();
    RefImage ref = referenceImage(kWidth, kHeight, SurfaceFormat::Color, false,
                                  [&](Eval& ev, PixelPos p) { return directionalLightPixel(ev, gb, q, p); });
    check("DirectionalLight", gpu, ref);
}

TEST_F(DeferredPasses, SpotLightWithoutShadows) { spotTest("SpotLight.NoShadows", false); }
TEST_F(DeferredPasses, SpotLightWithShadowsAndCookie) { spotTest("SpotLight.Shadows", true); }
TEST_F(DeferredPasses, PointLightWithoutShadows) { pointTest("PointLight.NoShadows", false); }
TEST_F(DeferredPasses, PointLightWithCubeShadows) { pointTest("PointLight.Shadows", true); }

TEST_F(DeferredPasses, Composition) {
    PassInputs& s = in();
    ShippedRenderer& r = shipped();
    upload(r.gbuffer(0), s.gbuffer.albedo);
    upload(r.renderer->getLightMap(), s.lightMap);
    RenderTarget2D scene(device, kWidth, kHeight, false, SurfaceFormat::Color, DepthFormat::Depth24Stencil8);
    r.renderer->MakeFinal(device, &scene);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    RefImage ref = referenceImage(kWidth, kHeight, SurfaceFormat::Color, false, [&](Eval& ev, PixelPos p) {
        return compositionPixel(ev, s.gbuffer.albedo, s.lightMap, {kWidth, kHeight}, p);
    });
    check("Composition", readBack(scene), ref);
}

TEST_F(DeferredPasses, Ssao) {
    PassInputs& s = in();
    ShippedRenderer& r = shipped();
    uploadGBuffer(r, s);
    const float sampleRadius = 0.25f, distanceScale = 3.0f;  // fxdemo's starting values
    r.ssao->setSampleRadius(sampleRadius);
    r.ssao->setDistanceScale(distanceScale);
    FixedCamera camera(s.camera);
    r.ssao->RenderSSAO(device, r.renderer->getGBuffer(), camera);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    RenderTarget2D& target = r.ssao->getSSAOTarget();
    // SSAO samples the content's random normals (RandomNormals.png, no mip levels): the reference reads the same texels.
    const CpuTexture randomNormals = r.randomNormals();
    SsaoParams q;
    q.projection = toM4(s.camera.Projection);
    float cy = float(std::tan(double(s.camera.FieldOfView) / 2.0)) * s.camera.FarPlane;
    q.cornerFustrum = {double(cy * s.camera.AspectRatio), double(cy), double(s.camera.FarPlane)};
    q.sampleRadius = sampleRadius;
    q.distanceScale = distanceScale;
    q.gbufferTextureSize = {kWidth, kHeight};
    RefImage ref = referenceImage(kWidth, kHeight, SurfaceFormat::Color, false, [&](Eval& ev, PixelPos p) {
        return ssaoPixel(ev, s.gbuffer.normals, s.gbuffer.depth, randomNormals, q, p);
    });
    check("SSAO", readBack(target), ref);
}

TEST_F(DeferredPasses, SsaoBlur) {
    PassInputs& s = in();
    ShippedRenderer& r = shipped();
    upload(r.ssao->getSSAOTarget(), s.ssao);
    // BlurSSAO relies on RenderSSAO having set Textures[1] = GBuffer 1 (LinearClamp).
    uploadGBuffer(r, s);
    device.Textures[1] = &r.gbuffer(1);
    device.SamplerStates[1] = SamplerState::LinearClamp;
    r.ssao->BlurSSAO(device);
    RenderTarget2D& target = r.ssao->getBlurTarget();
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    V2 blurDirection{double(1.0f / float(kWidth)), double(1.0f / float(kHeight))};
    RefImage ref = referenceImage(kWidth, kHeight, SurfaceFormat::Color, false, [&](Eval& ev, PixelPos p) {
        return ssaoBlurPixel(ev, s.gbuffer.normals, s.ssao, blurDirection, {kWidth, kHeight}, p);
    });
    check("SSAOBlur", readBack(target), ref);
}

TEST_F(DeferredPasses, SsaoFinal) {
    PassInputs& s = in();
    ShippedRenderer& r = shipped();
    // Compose(useBlurredSSAO = true) reads the blurred target: the inputs' SSAO image goes there.
    upload(r.ssao->getBlurTarget(), s.ssao);
    RenderTarget2D scene(device, kWidth, kHeight, false, SurfaceFormat::Color, DepthFormat::None);
    upload(scene, s.sceneImage);
    RenderTarget2D target(device, kWidth, kHeight, false, SurfaceFormat::Color, DepthFormat::None);
    r.ssao->Compose(device, &scene, &target, true);
    device.SetRenderTarget(static_cast<RenderTarget2D*>(nullptr));
    V2 halfPixel{double(1.0f / float(kWidth)), double(1.0f / float(kHeight))};
    RefImage ref = referenceImage(kWidth, kHeight, SurfaceFormat::Color, false,
                                  [&](Eval& ev, PixelPos p) { return ssaoFinalPixel(ev, s.sceneImage, s.ssao, halfPixel, p); });
    check("SSAOFinal", readBack(target), ref);
}

}  // namespace
}  // namespace fxport::render_test
