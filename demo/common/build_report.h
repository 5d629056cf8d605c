// fxport addition (issue 6): what a demo built -- the effects its ContentManager loaded
// (techniques, passes, load time), the render targets that exist (size, formats, bytes) and the
// passes its frames ran (GpuTimer sections) -- and `fxdemo <name> --explain`'s printout of one
// scene's build against the all-features scene's. Each demo lists its own targets; the effects and
// passes come from the ContentManager and the GpuTimer.
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "fxport/framework.h"
#include "fxport/graphics.h"

namespace fxport::demo {

struct BuildReport {
    struct EffectEntry {
        std::string asset;                    // "Effects/SpotLight"
        std::vector<std::string> techniques;  // "Name(passes)", "+" appended when it was compiled
        int passes = 0;
        // Effect::statistics(): the outline at load, then the techniques compiled at their first
        // Apply (xlate, cache hits included) and their GL programs.
        double loadMs = 0;
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
    std::vector<double> passMs;       // their median ms (for the bounds of --bounds)
    DepthStorageStatistics depthStorage;  // GraphicsDevice::depthStorageStatistics(), by addClears too
    // GraphicsDevice::clearStatistics() since the device was made (issue 16), once addClears ran.
    bool hasClears = false;
    ClearStatistics clears;
    ComputePassStatistics computePasses;  // DeviceOptimizations::ComputePasses (taken with the clears)

    std::int64_t targetBytes() const;
    double effectLoadMs() const;
    bool hasEffect(const std::string& asset) const;
    // Targets whose name starts with `prefix` ("SpotLight.shadowMap", "SSAO").
    int countTargets(const std::string& prefix) const;
    bool hasPass(const std::string& name) const;

    // Filling it in: every effect `content` loaded, in load order; a target; the timer's sections
    // (call after GpuTimer::Finish).
    void addLoadedEffects(const ContentManager& content);
    // One effect the demo created itself (not through a ContentManager), listed as `name`.
    void addEffect(const std::string& name, Effect& effect);
    void addTarget(const RenderTarget2D& target);
    void addTarget(const RenderTargetCube& target);
    void addPasses(const GpuTimer& timer);
    void addClears(const GraphicsDevice& device);
};

// Bytes a render target holds: width x height x faces x the format's texel size, plus its depth
// buffer (one per target, shared by a cube's faces; 24-bit depth counted as 4 bytes, as drivers
// store it).
std::int64_t RenderTargetBytes(int width, int height, int faces, SurfaceFormat format, DepthFormat depth);

// Prints `built` against `allFeatures` (described by `allFeaturesText`): each effect, target and
// pass as built or left out, with load times and bytes, and the totals.
void PrintExplain(std::FILE* out, const BuildReport& built, const BuildReport& allFeatures, const char* allFeaturesText);

}  // namespace fxport::demo
