#include "pointlights/build_report.h"

namespace DeferredLighting {

BuildReport ReportBuild(Game1& game, const GpuTimer* timer) {
    BuildReport report;
    report.addLoadedEffects(game.Content);
    DeferredRenderer& renderer = game.getRenderer();
    report.addTarget(renderer.getColorRT());
    report.addTarget(renderer.getNormalRT());
    report.addTarget(renderer.getDepthRT());
    report.addTarget(renderer.getLightRT());
    if (timer) report.addPasses(*timer);
    report.addClears(*game.GraphicsDevice);
    report.pointLightsDrawn = renderer.insideLights + renderer.outsideLights;
    report.pointLightsCulled = renderer.culledLights;
    return report;
}

void ExplainAgainstAllFeatures(std::FILE* out, const Game1& game, const BuildReport& built) {
    // The all-features game has its own device: the main run's --check-finite scan stays with it.
    FiniteCheck* const mainRunCheck = PassTimer::finiteCheck;
    PassTimer::finiteCheck = nullptr;
    BuildReport all;
    {
        Game1 everything;
        everything.graphics = game.graphics;
        everything.demo = game.demo;
        everything.Content.RootDirectory = game.Content.RootDirectory;
        everything.Content.EffectDirectory = game.Content.EffectDirectory;
        everything.Content.effectOptions = game.Content.effectOptions;
        everything.Start();
        everything.getRenderer().drawSpotLight = true;
        everything.getRenderer().frustumCulling = false;
        GpuTimer timer(*everything.GraphicsDevice);
        everything.getRenderer().setGpuTimer(&timer);
        everything.Tick();
        timer.EndFrame();
        timer.Finish();
        all = ReportBuild(everything, &timer);
        everything.getRenderer().setGpuTimer(nullptr);
    }
    PassTimer::finiteCheck = mainRunCheck;

    fxport::demo::PrintExplain(out, built, all,
                               "the chapter's lights and the exercise's spot light, no frustum culling; same size, "
                               "camera, time and knobs");
    std::fprintf(out, "point lights in the last frame: %d drawn, %d culled (all-features: %d drawn)\n", built.pointLightsDrawn,
                 built.pointLightsCulled, all.pointLightsDrawn);
}

}  // namespace DeferredLighting
