// The deferred demo builds only what its scene uses (issue 6 part 3): Game1 run headless at a small
// size, and what it built read from the live objects (deferred/build_report.h: ContentManager's load
// log, the targets that exist, the passes the GpuTimer saw, the renderer's light counts).
#include <algorithm>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "deferred/build_report.h"
#include "deferred/game1.h"

namespace TheCansinDeferredRenderer {
namespace {

constexpr int kWidth = 160, kHeight = 96;

// A Game1 at the test size with the fxdemo viewpoint (the seed's three lights in view), started.
struct TestGame {
    Game1 game;
    std::unique_ptr<GpuTimer> timer;

    explicit TestGame(void (*configure)(Game1::DemoSettings&) = nullptr) {
        game.graphics.PreferredBackBufferWidth = kWidth;
        game.graphics.PreferredBackBufferHeight = kHeight;
        game.demo.cameraPosition = Vector3(0.0f, 9.0f, 17.0f);
        game.demo.cameraTarget = Vector3(0.0f, 1.5f, 0.0f);
        game.demo.sampleRadius = 0.25f;
        game.demo.distanceScale = 3.0f;
        game.demo.debugViews = false;
        if (configure) configure(game.demo);
        game.Start();
        timer = std::make_unique<GpuTimer>(*game.GraphicsDevice);
        game.getDeferredRenderer().setGpuTimer(timer.get());
        if (game.hasSSAO()) game.getSSAO().setGpuTimer(timer.get());
        game.demo.gpuTimer = timer.get();
    }
    ~TestGame() { game.demo.gpuTimer = nullptr; }

    void keepLights(const std::string& kinds) {
        Lights::LightManager& lights = game.getLightManager();
        auto keep = [&](char c) { return kinds.find(c) != std::string::npos; };
        while (!keep('d') && !lights.getDirectionalLights().empty()) lights.RemoveLight(lights.getDirectionalLights()[0].get());
        while (!keep('s') && !lights.getSpotLights().empty()) lights.RemoveLight(lights.getSpotLights()[0].get());
        while (!keep('p') && !lights.getPointLights().empty()) lights.RemoveLight(lights.getPointLights()[0].get());
    }

    BuildReport frame() {
        game.Tick();
        timer->EndFrame();
        timer->Finish();
        return ReportBuild(game, timer.get());
    }
};

std::set<std::string> effectsOf(const BuildReport& report) {
    std::set<std::string> names;
    for (const auto& e : report.effects) names.insert(e.asset);
    return names;
}

std::set<std::string> targetsOf(const BuildReport& report) {
    std::set<std::string> names;
    for (const auto& t : report.targets) names.insert(t.name);
    return names;
}

bool loaded(Game1& game, const std::string& asset) {
    const auto& log = game.Content.loadLog();
    return std::any_of(log.begin(), log.end(), [&](const auto& r) { return r.assetName == asset; });
}

TEST(DeferredScene, DirectionalOnlySceneMakesNoShadowSsaoSpotOrPointResources) {
    TestGame t([](Game1::DemoSettings& demo) { demo.ssao = false; });
    t.keepLights("d");
    const BuildReport report = t.frame();

    EXPECT_EQ(effectsOf(report), (std::set<std::string>{"Effects/Clear", "Effects/GBuffer", "Effects/Composition",
                                                         "Effects/DirectionalLight"}));
    EXPECT_EQ(targetsOf(report), (std::set<std::string>{"GBuffer0", "GBuffer1", "GBuffer2", "LightMap"}));
    EXPECT_FALSE(loaded(t.game, "SpotLightGeometry"));
    EXPECT_FALSE(loaded(t.game, "PointLightGeometry"));
    EXPECT_FALSE(t.game.hasSSAO());
    EXPECT_THROW(t.game.getSSAO(), InvalidOperation);
    EXPECT_FALSE(report.hasPass("ShadowMaps"));
    EXPECT_FALSE(report.hasPass("SSAO"));
    EXPECT_TRUE(report.hasPass("LightMap"));
    EXPECT_EQ(report.lights.directionalLightsDrawn, 1);
    EXPECT_EQ(report.lights.spotLightsDrawn + report.lights.pointLightsDrawn, 0);
}

TEST(DeferredScene, FullSceneBuildsEverythingItUses) {
    TestGame t;
    const BuildReport report = t.frame();
    for (const char* effect : {"Effects/DepthWriter", "Effects/SpotLight", "Effects/PointLight", "Effects/SSAO",
                               "Effects/SSAOBlur", "Effects/SSAOFinal"})
        EXPECT_TRUE(report.hasEffect(effect)) << effect;
    EXPECT_EQ(report.countTargets("SpotLight.shadowMap"), 1);
    EXPECT_EQ(report.countTargets("PointLight.shadowMap"), 1);
    EXPECT_EQ(report.countTargets("SSAOTarget") + report.countTargets("BlurTarget") + report.countTargets("Scene"), 3);
    EXPECT_TRUE(report.hasPass("ShadowMaps"));
    EXPECT_TRUE(report.hasPass("SSAOBlur"));
    EXPECT_EQ(report.lights.spotLightsDrawn, 1);
    EXPECT_EQ(report.lights.pointLightsDrawn, 1);
}

TEST(DeferredScene, SsaoOffHasNoSsaoTargetOrEffect) {
    TestGame t([](Game1::DemoSettings& demo) { demo.ssao = false; });
    const BuildReport report = t.frame();
    EXPECT_EQ(report.countTargets("SSAOTarget") + report.countTargets("BlurTarget") + report.countTargets("Scene"), 0);
    for (const auto& e : report.effects) EXPECT_EQ(e.asset.find("SSAO"), std::string::npos) << e.asset;
    EXPECT_FALSE(report.hasPass("SSAO"));
    EXPECT_FALSE(report.hasPass("SSAOFinal"));
    // The lights are unaffected.
    EXPECT_EQ(report.countTargets("SpotLight.shadowMap"), 1);
}

TEST(DeferredScene, KnobsSizeTheTargets) {
    TestGame t([](Game1::DemoSettings& demo) {
        demo.ssaoHalfResolution = true;
        demo.spotShadowMapSize = 512;
        demo.pointShadowMapSize = 64;
        demo.gbufferFormats = Game1::DemoSettings::GBufferFormats::Color8;
    });
    const BuildReport report = t.frame();
    std::vector<std::string> seen;
    for (const auto& target : report.targets) {
        seen.push_back(target.name);
        if (target.name == "SSAOTarget" || target.name == "BlurTarget") {
            EXPECT_EQ(target.width, kWidth / 2);
            EXPECT_EQ(target.height, kHeight / 2);
        } else if (target.name == "SpotLight.shadowMap") {
            EXPECT_EQ(target.width, 512);
        } else if (target.name == "PointLight.shadowMap") {
            EXPECT_EQ(target.width, 64);
            EXPECT_EQ(target.faces, 6);
            // 64 x 64 x 6 faces x 4 bytes (Single) + one 64 x 64 depth-stencil buffer of 4 bytes.
            EXPECT_EQ(target.bytes, 64 * 64 * 6 * 4 + 64 * 64 * 4);
        } else if (target.name == "GBuffer0" || target.name == "GBuffer1") {
            EXPECT_EQ(target.format, SurfaceFormat::Color);
        } else if (target.name == "GBuffer2") {
            EXPECT_EQ(target.format, SurfaceFormat::Single);
        }
    }
    EXPECT_EQ(seen.size(), 9u);
}

TEST(DeferredScene, OutOfRangeKnobIsRefusedByName) {
    try {
        TestGame t([](Game1::DemoSettings& demo) { demo.pointShadowMapSize = 2048; });
        FAIL() << "pointShadowMapSize 2048 was accepted";
    } catch (const ArgumentError& e) {
        EXPECT_NE(std::string(e.what()).find("pointShadowMapSize = 2048"), std::string::npos) << e.what();
    }
}

// The fxdemo viewpoint, at (0, 9, 17) looking towards -z, with the spot and point lights moved far
// behind it (z = 300 and 200): their volumes (a cone 100 long, a sphere of radius 20) are out of
// view, and the directional light still lights the courtyard.
TEST(DeferredScene, LightsOutsideTheFrustumAreNotDrawnAndChangeNoPixel) {
    TestGame t;
    t.game.getLightManager().getSpotLights()[0]->setPosition(Vector3(0, 15.0f, 300.0f));
    t.game.getLightManager().getPointLights()[0]->setPosition(Vector3(0, 5.0f, 200.0f));
    const BuildReport culled = t.frame();
    EXPECT_EQ(culled.lights.directionalLightsDrawn, 1);
    EXPECT_EQ(culled.lights.spotLightsDrawn, 0);
    EXPECT_EQ(culled.lights.spotLightsCulled, 1);
    EXPECT_EQ(culled.lights.pointLightsDrawn, 0);
    EXPECT_EQ(culled.lights.pointLightsCulled, 1);
    // Not seen: no shadow maps made (the lights cast shadows).
    EXPECT_EQ(culled.countTargets("SpotLight.shadowMap"), 0);
    EXPECT_EQ(culled.countTargets("PointLight.shadowMap"), 0);
    const std::vector<Color> withCulling = t.game.GraphicsDevice->GetBackBufferData();
    // The frame shows the lit courtyard, not one flat colour.
    EXPECT_GT(std::count_if(withCulling.begin(), withCulling.end(), [&](Color c) { return c != withCulling[0]; }),
              kWidth * kHeight / 2);

    // The same frame with every light drawn: the culled lights lit nothing the camera sees.
    t.game.getDeferredRenderer().frustumCulling = false;
    const BuildReport drawn = t.frame();
    EXPECT_EQ(drawn.lights.spotLightsDrawn, 1);
    EXPECT_EQ(drawn.lights.pointLightsDrawn, 1);
    EXPECT_EQ(drawn.countTargets("SpotLight.shadowMap"), 1);
    EXPECT_EQ(drawn.countTargets("PointLight.shadowMap"), 1);
    EXPECT_TRUE(withCulling == t.game.GraphicsDevice->GetBackBufferData());
}

// A spot light behind the camera, pointing away from the view: its cone (90 degrees, 100 long) lies
// wholly behind the near plane, while the cone mesh's bounding sphere (radius ~100) reaches far
// into the view, so only the cone test culls it. Turned round towards the courtyard, it is drawn.
TEST(DeferredScene, SpotConeBehindTheCameraIsCulledThoughItsBoundingSphereIsInView) {
    TestGame t;
    Lights::SpotLight& spot = *t.game.getLightManager().getSpotLights()[0];
    spot.setPosition(Vector3(0, 15.0f, 40.0f));
    spot.setDirection(Vector3(0, 0, 1));
    const BuildReport away = t.frame();
    EXPECT_EQ(away.lights.spotLightsDrawn, 0);
    EXPECT_EQ(away.lights.spotLightsCulled, 1);
    const std::vector<Color> withCulling = t.game.GraphicsDevice->GetBackBufferData();
    // The sphere test the cone replaced would have drawn it: check that premise.
    const BoundingSphere sphere =
        t.game.Content.Load<Model>("SpotLightGeometry")->Meshes[0].BoundingSphere.Transform(spot.getWorld());
    EXPECT_TRUE(BoundingFrustum(t.game.getCamera().View * t.game.getCamera().Projection).Intersects(sphere));
    // Drawn anyway, it lights no pixel the camera sees.
    t.game.getDeferredRenderer().frustumCulling = false;
    EXPECT_EQ(t.frame().lights.spotLightsDrawn, 1);
    EXPECT_TRUE(withCulling == t.game.GraphicsDevice->GetBackBufferData());

    t.game.getDeferredRenderer().frustumCulling = true;
    spot.setDirection(Vector3(0, -15.0f, -40.0f));
    const BuildReport towards = t.frame();
    EXPECT_EQ(towards.lights.spotLightsDrawn, 1);
    EXPECT_EQ(towards.lights.spotLightsCulled, 0);
}

TEST(DeferredScene, LightInViewIsDrawn) {
    TestGame t;  // the default viewpoint sees all three lights
    const BuildReport report = t.frame();
    EXPECT_EQ(report.lights.pointLightsCulled + report.lights.spotLightsCulled, 0);
}

// A light type the scene lacked at start is built when it appears, and the frame is the one a
// scene that had it from the start draws.
TEST(DeferredScene, LightTypeAddedLaterIsBuiltThenAndDrawsTheSameFrame) {
    std::vector<Color> fromStart;
    {
        TestGame t([](Game1::DemoSettings& demo) { demo.ssao = false; });
        t.keepLights("ds");
        t.frame();
        fromStart = t.game.GraphicsDevice->GetBackBufferData();
    }
    TestGame t([](Game1::DemoSettings& demo) { demo.ssao = false; });
    t.keepLights("d");
    const BuildReport before = t.frame();
    EXPECT_FALSE(before.hasEffect("Effects/SpotLight"));
    EXPECT_FALSE(before.hasEffect("Effects/DepthWriter"));

    // The seed's spot light, as Game1::LoadContent adds it.
    t.game.getLightManager().AddLight(std::make_unique<Lights::SpotLight>(
        *t.game.GraphicsDevice, Vector3(0, 15.0f, 0), Vector3(0, -1, 0), Color::White.ToVector4(), 0.10f, true, 2048,
        t.game.Content.Load<Texture2D>("SpotCookie")));
    const BuildReport after = t.frame();
    EXPECT_TRUE(after.hasEffect("Effects/SpotLight"));
    EXPECT_TRUE(after.hasEffect("Effects/DepthWriter"));
    EXPECT_EQ(after.countTargets("SpotLight.shadowMap"), 1);
    EXPECT_EQ(after.lights.spotLightsDrawn, 1);
    EXPECT_TRUE(fromStart == t.game.GraphicsDevice->GetBackBufferData());
}

}  // namespace
}  // namespace TheCansinDeferredRenderer
