// fxport addition (issue 6): what a Game1 built (common/build_report.h: effects, render targets,
// passes) and the lights its last frame drew or culled, read from the live objects -- the renderer's,
// SSAO's and the lights' targets. `fxdemo deferred --explain` prints one scene's report against the
// all-features scene's; tests assert on it.
#pragma once

#include <cstdio>

#include "common/build_report.h"
#include "deferred/game1.h"

namespace TheCansinDeferredRenderer {

struct BuildReport : fxport::demo::BuildReport {
    DeferredRenderer::FrameStats lights;
    int shadowMapsDrawn = 0, shadowMapsReused = 0;  // LightManager's counts over the run's frames
    bool reuseShadowMaps = true;
};

// `timer`: the game's GpuTimer (Finish()ed), for the passes; nullptr leaves passes empty.
BuildReport ReportBuild(Game1& game, const GpuTimer* timer);

// Prints `built` against `allFeatures`, then the lights the last frame drew and culled.
void PrintExplain(std::FILE* out, const BuildReport& built, const BuildReport& allFeatures);

}  // namespace TheCansinDeferredRenderer
