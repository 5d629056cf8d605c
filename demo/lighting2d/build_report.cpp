#include "lighting2d/build_report.h"

namespace _2DLightingSystem {

BuildReport ReportBuild(const ContentManager& content, const LightRenderer& renderer, const GpuTimer* timer) {
    BuildReport report;
    report.addLoadedEffects(content);
    for (const auto* target : {&renderer.backBufferCache, &renderer.midGroundTarget, &renderer.lightMap,
                               &renderer.unwrapTarget, &renderer.occlusionMap, &renderer.postProcessTarget,
                               &renderer.horizontalBlurTarget, &renderer.verticalBlurTarget})
        if (*target) report.addTarget(**target);
    if (timer) report.addPasses(*timer);
    report.addClears(renderer.GraphicsDevice);
    report.spotLights = int(renderer.spotLights.size());
    report.pointLights = int(renderer.pointLights.size());
    return report;
}

}  // namespace _2DLightingSystem
