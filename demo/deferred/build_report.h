// fxport addition (issue 6): what a Game1 built -- the effects it loaded (techniques, passes, load
// time), the render targets that exist (size, formats, bytes), the passes its frames ran and the
// lights the last frame drew or culled -- read from the live objects (ContentManager's load log,
// the renderer's, SSAO's and the lights' targets, the GpuTimer's sections). `fxdemo deferred
// --explain` prints one scene's report against the all-features scene's; tests assert on it.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "deferred/game1.h"

namespace TheCansinDeferredRenderer {

struct BuildReport {
    struct EffectEntry {
        std::string asset;                    // "Effects/SpotLight"
        std::vector<std::string> techniques;  // "Name(passes)"
        int passes = 0;
        double loadMs = 0;                    // xlate's compile (or cache hit) and the GL programs
    };
    struct TargetEntry {
        std::string name;
        int width = 0, height = 0, faces = 1;  // faces: 6 for a cube map
        SurfaceFormat format = SurfaceFormat::Color;
        DepthFormat depth = DepthFormat::None;
        std::int64_t bytes = 0;                // colour faces and the depth buffer
    };
    std::vector<EffectEntry> effects;
    std::vector<TargetEntry> targets;
    std::vector<std::string> passes;  // GpuTimer sections that ran, in order ("frame" left out)
    DeferredRenderer::FrameStats lights;

    std::int64_t targetBytes() const;
    double effectLoadMs() const;
    bool hasEffect(const std::string& asset) const;
    // Targets whose name starts with `prefix` ("SpotLight.shadowMap", "SSAO").
    int countTargets(const std::string& prefix) const;
    bool hasPass(const std::string& name) const;
};

// Bytes a render target holds: width x height x faces x the format's texel size, plus its depth
// buffer (one per target, shared by a cube's faces; 24-bit depth counted as 4 bytes, as drivers
// store it).
std::int64_t RenderTargetBytes(int width, int height, int faces, SurfaceFormat format, DepthFormat depth);

// `timer`: the game's GpuTimer (Finish()ed), for the passes; nullptr leaves passes empty.
BuildReport ReportBuild(Game1& game, const GpuTimer* timer);

// Prints `built` against `allFeatures`: each effect, target and pass as built or left out, with
// load times and bytes, and the totals.
void PrintExplain(std::FILE* out, const BuildReport& built, const BuildReport& allFeatures);

}  // namespace TheCansinDeferredRenderer
