// fxport addition (issue 6): what `fxdemo lighting2d` built (common/build_report.h): the effects its
// ContentManager loaded (a light type's unwrap and light effects only when a light of that type is
// drawn), the LightRenderer's eight targets, the passes run, and the lights drawn of each type.
#pragma once

#include "common/build_report.h"
#include "fxport/framework.h"
#include "lighting2d/light_renderer.h"

namespace _2DLightingSystem {

struct BuildReport : fxport::demo::BuildReport {
    int spotLights = 0;
    int pointLights = 0;
};

// `timer`: the game's GpuTimer (Finish()ed), for the passes; nullptr leaves passes empty.
BuildReport ReportBuild(const ContentManager& content, const LightRenderer& renderer, const GpuTimer* timer);

}  // namespace _2DLightingSystem
