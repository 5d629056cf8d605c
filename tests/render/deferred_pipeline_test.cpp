// The whole deferred frame end to end, as demo/deferred draws it (Game1.Draw with SSAO): shadow
// maps -> clear G-buffer -> G-buffer -> light map (directional + spot with cookie and shadows +
// point with cube shadows) -> composition -> SSAO -> blur -> final, with the final chapter's light
// setup (at the tests' small sizes), rendered headless at 96x64. The shipped code draws every stage,
// as Game1.Draw calls it (shipped_renderer.h): LightManager.DrawShadowMaps and DeferredRenderer.Draw
// of the tests' scene mesh as a Model, then SSAO.Draw. The light volumes are the content's models,
// as the demo has them. SSAO samples the tests' 16x16 random normals (SSAO::setRandomNormals), not
// the content's 64x64 texture: with that one, one pixel of the reference chain (reference G-buffer
// in, not the GPU's) leaves its derived bound (0.0248 > 0.0183: the first-order slack does not see
// a depth comparison flip); the per-pass SSAO test runs with the content's texture.
//
// Two comparisons per stage:
//  * "E2E.<stage>": the reference composed from the per-pass references -- each reference stage
//    reads the previous reference stages (rounded to their target formats), never the GPU's images.
//    A reference stage used as input carries, per texel, half its range + its format bound + its
//    slack, and reference_eval.h propagates that into each later pixel's slack, so the bound of the
//    final image is derived, not chosen.
//  * "Frame.<stage>": the same pass's reference evaluated on the GPU's own inputs of this frame
//    (the per-pass test on real pipeline data): the tight bound of the per-pass tests.
#include <gtest/gtest.h>

#include <functional>
#include <memory>

#include "reference/deferred_reference.h"
#include "deferred_scene.h"
#include "light_params.h"
#include "render_harness.h"
#include "runtime_test_support.h"
#include "shipped_renderer.h"

namespace fxport::render_test {
namespace {

constexpr int W = kWidth, H = kHeight;

std::vector<std::vector<int>> perPixel(int width, int height, const std::function<std::vector<int>(int, int)>& f) {
    std::vector<std::vector<int>> out;
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) out.push_back(f(x, y));
    return out;
}

Range4 clamped(Range4 r) {
    for (int c = 0; c < 4; ++c) {
        r.lo[c] = std::clamp(r.lo[c], 0.0, 1.0);
        r.hi[c] = std::clamp(r.hi[c], 0.0, 1.0);
    }
    return r;
}

Range4 operator+(const Range4& a, const Range4& b) { return {a.lo + b.lo, a.hi + b.hi, a.exact && b.exact}; }

// The frame's fixed inputs (Game1.LoadContent's lights, fxdemo's camera and SSAO values) and the
// reference of every stage as a function of that stage's input textures.
struct Frame {
    explicit Frame(ShippedRenderer& shipped)
        : cone(shipped.lightVolume("SpotLightGeometry")), sphere(shipped.lightVolume("PointLightGeometry")) {}
    TestCamera camera = makeCamera(Vector3(0, 9, 17), Vector3(0, 1.5f, 0), W, H);
    DirectionalLightSetup directional{Vector3::Down, Color::White.ToVector4(), 0.05f};
    SpotLightSetup spot = makeSpotLight(Vector3(0, 15, 0), Vector3(0, -1, 0), Color::White.ToVector4(), 0.10f, true, 64);
    PointLightSetup point{Vector3(0, 5, 0), 20, Color::White.ToVector4(), 0.80f, true, 32};
    float sampleRadius = 0.25f, distanceScale = 3.0f;
    Mesh scene = testSceneMesh(), cone, sphere;  // the light volumes: the content's models
    Materials materials = makeMaterials();
    CpuTexture cookie = makeSpotCookie(32), randomNormals = makeRandomNormals(16);
    View3D cameraView = makeView(toM4(camera.View), toM4(camera.Projection), W, H);
    V2 size{double(W), double(H)};
    V2 step{double(1.0f / float(W)), double(1.0f / float(H))};  // blurDirection, halfPixel

    RefImage shadowMap(int face) const {  // face < 0: the spot light's map
        DepthWriterPass pass;
        pass.mesh = &scene;
        pass.world = M4::identity();
        pass.worldMesh = toWorld(scene, pass.world);
        int n = face < 0 ? spot.ShadowMapResolution : point.ShadowMapResolution;
        if (face < 0) {
            pass.lightView = makeView(toM4(spot.View), toM4(spot.Projection), n, n);
            pass.lightPosition = toV3(spot.Position);
            pass.depthPrecision = spot.FarPlane;
        } else {
            pass.lightView = makeView(toM4(point.FaceView(CubeMapFace(face))), toM4(point.FaceProjection()), n, n);
            pass.lightPosition = toV3(point.Position);
            pass.depthPrecision = point.Radius;
        }
        auto visible = perPixel(n, n, [&](int x, int y) {
            return visibleCandidates(pass.worldMesh, pass.lightView, Cull::CounterClockwiseFace, x, y);
        });
        return referenceImage(n, n, SurfaceFormat::Single, true, [&](Eval& ev, PixelPos p) {
            return depthWriterPixel(ev, pass, visible[std::size_t(p.y * n + p.x)], p);
        });
    }

    RefImage gbuffer(int target) const {
        GBufferPass pass;
        pass.mesh = &scene;
        pass.world = M4::identity();
        pass.worldMesh = toWorld(scene, pass.world);
        pass.camera = cameraView;
        pass.view = toM4(camera.View);
        pass.projection = toM4(camera.Projection);
        pass.worldViewIT = toM4(Matrix::Transpose(Matrix::Invert(Matrix::Identity * camera.View)));
        pass.albedoMap = &materials.albedo;
        pass.normalMap = &materials.normal;
        pass.specularMap = &materials.specular;
        auto visible = perPixel(W, H, [&](int x, int y) {
            return visibleCandidates(pass.worldMesh, cameraView, Cull::CounterClockwiseFace, x, y);
        });
        SurfaceFormat format = target == 2 ? SurfaceFormat::Vector2 : SurfaceFormat::Rgba64;
        return referenceImage(W, H, format, true, [&](Eval& ev, PixelPos p) {
            return gbufferPixel(ev, pass, visible[std::size_t(p.y * W + p.x)], p, target);
        });
    }

    // Three lights blended additively into an 8-bit target; each fragment is clamped and rounded
    // before the blend, so the bound is three times the 8-bit one.
    RefImage lightMap(const GBufferTextures& gb, const CpuTexture& spotShadow, const CpuCube& cube) const {
        DirectionalLightParams dq = directionalParams(camera, directional);
        SpotLightParams sq = spotParams(camera, spot);
        PointLightParams pq = pointParams(camera, point);
        // The demo's cull modes (the camera is outside the cone and inside the sphere).
        WorldMesh coneWorld = toWorld(cone, toM4(spot.World)), sphereWorld = toWorld(sphere, toM4(point.World()));
        Cull spotCull = render_test::spotCull(camera, spot), pointCull = render_test::pointCull(camera, point);
        auto spotCoverage = perPixel(W, H, [&](int x, int y) { return coverageCandidates(coneWorld, cameraView, spotCull, x, y); });
        auto pointCoverage = perPixel(W, H, [&](int x, int y) { return coverageCandidates(sphereWorld, cameraView, pointCull, x, y); });
        RefImage ref = referenceImage(W, H, SurfaceFormat::Color, true, [&](Eval& ev, PixelPos p) {
            std::size_t i = std::size_t(p.y * W + p.x);
            return clamped(directionalLightPixel(ev, gb, dq, p)) +
                   clamped(spotLightPixel(ev, gb, cookie, spotShadow, sq, spotCoverage[i], p)) +
                   clamped(pointLightPixel(ev, gb, cube, pq, pointCoverage[i], p));
        });
        ref.boundScale = 3;
        return ref;
    }

    RefImage composition(const CpuTexture& albedo, const CpuTexture& light) const {
        return referenceImage(W, H, SurfaceFormat::Color, false,
                              [&](Eval& ev, PixelPos p) { return compositionPixel(ev, albedo, light, size, p); });
    }

    RefImage ssao(const CpuTexture& normals, const CpuTexture& depth) const {
        SsaoParams q;
        q.projection = toM4(camera.Projection);
        float cy = float(std::tan(double(camera.FieldOfView) / 2.0)) * camera.FarPlane;
        q.cornerFustrum = {double(cy * camera.AspectRatio), double(cy), double(camera.FarPlane)};
        q.sampleRadius = sampleRadius;
        q.distanceScale = distanceScale;
        q.gbufferTextureSize = size;
        return referenceImage(W, H, SurfaceFormat::Color, false,
                              [&](Eval& ev, PixelPos p) { return ssaoPixel(ev, normals, depth, randomNormals, q, p); });
    }

    RefImage blur(const CpuTexture& normals, const CpuTexture& ssaoImage) const {
        return referenceImage(W, H, SurfaceFormat::Color, false,
                              [&](Eval& ev, PixelPos p) { return ssaoBlurPixel(ev, normals, ssaoImage, step, size, p); });
    }

    RefImage final(const CpuTexture& sceneImage, const CpuTexture& blurred) const {
        return referenceImage(W, H, SurfaceFormat::Color, false,
                              [&](Eval& ev, PixelPos p) { return ssaoFinalPixel(ev, sceneImage, blurred, step, p); });
    }
};

// What the GPU rendered, read back.
struct GpuFrame {
    CpuTexture spotShadow;
    CpuCube cube;
    CpuTexture gbuffer[3], lightMap, scene, ssao, blur, final;
};

GpuFrame renderFrame(GraphicsDevice& device, Frame& f) {
    using namespace TheCansinDeferredRenderer;
    ShippedRenderer& r = shippedRenderer(device);
    Texture2D albedoMap(device, 16, 16, false, SurfaceFormat::Color), normalMap(device, 16, 16, false, SurfaceFormat::Color),
        specularMap(device, 16, 16, false, SurfaceFormat::Color), cookie(device, 32, 32, false, SurfaceFormat::Color),
        randomNormals(device, 16, 16, false, SurfaceFormat::Color);
    upload(albedoMap, f.materials.albedo);
    upload(normalMap, f.materials.normal);
    upload(specularMap, f.materials.specular);
    upload(cookie, f.cookie);
    upload(randomNormals, f.randomNormals);
    std::unique_ptr<Model> sceneModel = toModel(device, f.scene, {&albedoMap, &normalMap, &specularMap});
    const std::vector<Model*> models{sceneModel.get()};
    RenderTarget2D scene(device, W, H, false, SurfaceFormat::Color, DepthFormat::Depth24Stencil8);
    RenderTarget2D output(device, W, H, false, SurfaceFormat::Color, DepthFormat::None);

    // Game1.LoadContent's lights, as the demo's Lights classes; the references take their matrices.
    Lights::LightManager lights(r.content);
    lights.AddLight(std::make_unique<Lights::DirectionalLight>(f.directional.Direction, f.directional.Color, f.directional.Intensity));
    auto spot = std::make_unique<Lights::SpotLight>(device, f.spot.Position, f.spot.Direction, f.spot.Color, f.spot.Intensity,
                                                    f.spot.Shadows, f.spot.ShadowMapResolution, &cookie);
    f.spot.View = spot->getView();
    f.spot.Projection = spot->getProjection();
    f.spot.World = spot->getWorld();
    f.spot.Direction = spot->getDirection();
    auto point = std::make_unique<Lights::PointLight>(device, f.point.Position, f.point.Radius, f.point.Color, f.point.Intensity,
                                                      f.point.Shadows, f.point.ShadowMapResolution);
    RenderTarget2D& spotShadow = spot->MakeShadowMap();
    RenderTargetCube& pointShadow = point->MakeShadowMap();
    lights.AddLight(std::move(spot));
    lights.AddLight(std::move(point));
    FixedCamera camera(f.camera);

    // Game1.Draw with SSAO: the shadow maps, the deferred frame into Scene, SSAO into the output.
    lights.DrawShadowMaps(
        device, models, [&](const Lights::SpotLight& light) { return r.renderer->IsVisible(light, camera); },
        [&](const Lights::PointLight& light) { return r.renderer->IsVisible(light, camera); });
    EXPECT_EQ(lights.shadowMapsDrawn, 2);
    r.renderer->Draw(device, models, lights, camera, &scene);
    Texture2D& contentRandomNormals = r.ssao->getRandomNormals();
    r.ssao->setRandomNormals(randomNormals);
    r.ssao->setSampleRadius(f.sampleRadius);
    r.ssao->setDistanceScale(f.distanceScale);
    r.ssao->Draw(device, r.renderer->getGBuffer(), &scene, camera, &output);
    r.ssao->setRandomNormals(contentRandomNormals);  // the per-pass SSAO test samples the content's
    resetDevice(device);
    const auto& stats = r.renderer->getFrameStats();
    EXPECT_EQ(stats.directionalLightsDrawn + stats.spotLightsDrawn + stats.pointLightsDrawn, 3);

    GpuFrame g;
    g.spotShadow = readBack(spotShadow);
    g.cube.size = pointShadow.Size();
    for (int face = 0; face < 6; ++face) g.cube.faces[std::size_t(face)] = readBack(pointShadow, CubeMapFace(face));
    for (int t = 0; t < 3; ++t) g.gbuffer[t] = readBack(r.gbuffer(t));
    g.lightMap = readBack(r.renderer->getLightMap());
    g.scene = readBack(scene);
    g.ssao = readBack(r.ssao->getSSAOTarget());
    g.blur = readBack(r.ssao->getBlurTarget());
    g.final = readBack(output);
    return g;
}

void check(const std::string& name, const CpuTexture& gpu, const RefImage& ref, int channels = 4) {
    Comparison c = compare(name, gpu, ref, channels);
    report(c);
    EXPECT_EQ(c.failures, 0) << name << ": " << c.failures << " of " << c.samples << " samples outside the bound\n" << c.failureText;
    EXPECT_GE(c.shiftedFailureFraction, 0.5 * c.shiftVisibleFraction) << name << ": a one-pixel shift passes the bounds";
}

TEST(DeferredPipeline, WholeFrameMatchesComposedReference) {
    GraphicsDevice& device = test::testDevice();
    resetDevice(device);
    Frame f(shippedRenderer(device));
    GpuFrame gpu = renderFrame(device, f);

    // The reference chain.
    RefImage spotShadow = f.shadowMap(-1);
    check("E2E.SpotShadowMap", gpu.spotShadow, spotShadow, 1);
    CpuCube cube;
    cube.size = f.point.ShadowMapResolution;
    const char* faceNames[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    for (int face = 0; face < 6; ++face) {
        RefImage r = f.shadowMap(face);
        check(std::string("E2E.CubeShadow") + faceNames[face], gpu.cube.faces[std::size_t(face)], r, 1);
        cube.faces[std::size_t(face)] = asInput(r);
    }
    CpuTexture g[3];
    const char* gNames[3] = {"E2E.GBuffer.Albedo", "E2E.GBuffer.Normals", "E2E.GBuffer.Depth"};
    for (int t = 0; t < 3; ++t) {
        RefImage r = f.gbuffer(t);
        check(gNames[t], gpu.gbuffer[t], r);
        g[t] = asInput(r);
    }
    RefImage lightMap = f.lightMap({&g[0], &g[1], &g[2]}, asInput(spotShadow), cube);
    check("E2E.LightMap", gpu.lightMap, lightMap);
    RefImage scene = f.composition(g[0], asInput(lightMap));
    check("E2E.Composition", gpu.scene, scene);
    RefImage ssao = f.ssao(g[1], g[2]);
    check("E2E.SSAO", gpu.ssao, ssao);
    RefImage blur = f.blur(g[1], asInput(ssao));
    check("E2E.SSAOBlur", gpu.blur, blur);
    RefImage final = f.final(asInput(scene), asInput(blur));
    check("E2E.Final", gpu.final, final);
}

TEST(DeferredPipeline, EachStageMatchesItsReferenceOnTheFramesOwnInputs) {
    GraphicsDevice& device = test::testDevice();
    resetDevice(device);
    Frame f(shippedRenderer(device));
    GpuFrame gpu = renderFrame(device, f);
    GBufferTextures gb{&gpu.gbuffer[0], &gpu.gbuffer[1], &gpu.gbuffer[2]};
    check("Frame.LightMap", gpu.lightMap, f.lightMap(gb, gpu.spotShadow, gpu.cube));
    check("Frame.Composition", gpu.scene, f.composition(gpu.gbuffer[0], gpu.lightMap));
    check("Frame.SSAO", gpu.ssao, f.ssao(gpu.gbuffer[1], gpu.gbuffer[2]));
    check("Frame.SSAOBlur", gpu.blur, f.blur(gpu.gbuffer[1], gpu.ssao));
    check("Frame.Final", gpu.final, f.final(gpu.scene, gpu.blur));
}

}  // namespace
}  // namespace fxport::render_test
