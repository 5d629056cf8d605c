// fxport addition (issue 6): what `fxdemo pointlights` built (common/build_report.h: effects, the
// renderer's four targets, passes) and the point lights its last frame drew or culled; --explain
// prints it against the all-features scene (the exercise's spot light on, no frustum culling).
#pragma once

#include <cstdio>

#include "common/build_report.h"
#include "pointlights/game1.h"

namespace DeferredLighting {

struct BuildReport : fxport::demo::BuildReport {
    int pointLightsDrawn = 0;
    int pointLightsCulled = 0;
};

// `timer`: the game's GpuTimer (Finish()ed), for the passes; nullptr leaves passes empty.
BuildReport ReportBuild(Game1& game, const GpuTimer* timer);

// Builds the all-features scene -- a Game1 with `game`'s settings (size, platform, content, time,
// camera, quality), the spot light drawn and frustum culling off -- draws one frame, and prints
// `built` against it.
void ExplainAgainstAllFeatures(std::FILE* out, const Game1& game, const BuildReport& built);

}  // namespace DeferredLighting
