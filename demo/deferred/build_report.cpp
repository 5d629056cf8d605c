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
    report.lights = game.getDeferredRenderer().getFrameStats();
    return report;
}

void PrintExplain(std::FILE* out, const BuildReport& built, const BuildReport& allFeatures) {
    fxport::demo::PrintExplain(out, built, allFeatures,
                               "the seed's three lights with shadows, SSAO, no frustum culling; same size, camera and "
                               "knobs");
    const auto& l = built.lights;
    std::fprintf(out, "lights in the last frame: %d directional drawn; spot %d drawn, %d culled; point %d drawn, %d culled\n",
                 l.directionalLightsDrawn, l.spotLightsDrawn, l.spotLightsCulled, l.pointLightsDrawn, l.pointLightsCulled);
}

}  // namespace TheCansinDeferredRenderer
