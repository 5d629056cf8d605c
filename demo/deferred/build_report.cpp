#include "deferred/build_report.h"

namespace TheCansinDeferredRenderer {

BuildReport ReportBuild(Game1& game, const GpuTimer* timer) {
    BuildReport report;
    report.addLoadedEffects(game.Content);
    for (const RenderTarget2D* target : game.getDeferredRenderer().getTargets()) report.addTarget(*target);
    if (game.hasSSAO()) {
        report.addTarget(game.getScene());
        report.addTarget(game.getSSAO().getSSAOTarget());
        report.addTarget(game.getSSAO().getBlurTarget());
    }
    for (auto& light : game.getLightManager().getSpotLights())
        if (light->getShadowMap()) report.addTarget(*light->getShadowMap());
    for (auto& light : game.getLightManager().getPointLights())
        if (light->getShadowMap()) report.addTarget(*light->getShadowMap());
    if (timer) report.addPasses(*timer);
    report.addClears(*game.GraphicsDevice);
    report.lights = game.getDeferredRenderer().getFrameStats();
    report.shadowMapsDrawn = game.getLightManager().shadowMapsDrawn;
    report.shadowMapsReused = game.getLightManager().shadowMapsReused;
    report.reuseShadowMaps = game.getLightManager().reuseShadowMaps;
    return report;
}

void PrintExplain(std::FILE* out, const BuildReport& built, const BuildReport& allFeatures) {
    fxport::demo::PrintExplain(out, built, allFeatures,
                               "the seed's three lights with shadows, SSAO, no frustum culling; same size, camera and "
                               "knobs");
    const auto& l = built.lights;
    std::fprintf(out, "lights in the last frame: %d directional drawn; spot %d drawn, %d culled; point %d drawn, %d culled\n",
                 l.directionalLightsDrawn, l.spotLightsDrawn, l.spotLightsCulled, l.pointLightsDrawn, l.pointLightsCulled);
    std::fprintf(out, "shadow maps over the run's frames: %d drawn, %d reused (light and casters unchanged; cache %s)\n",
                 built.shadowMapsDrawn, built.shadowMapsReused, built.reuseShadowMaps ? "on" : "off, --no-shadow-cache");
}

}  // namespace TheCansinDeferredRenderer
