// `fxdemo deferred`: runs the port of "Deferred Rendering in XNA 4" (Game1) headless for a number of
// frames, or in a window, and writes what it rendered.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "deferred/game1.h"
#include "fxport/math.h"

namespace TheCansinDeferredRenderer {

struct RunOptions {
    int width = 800;                // the seed's PreferredBackBuffer size
    int height = 600;
    std::optional<int> frames;      // headless default 3; in a window: until it closes
    std::string outDir = "fxdemo-out";
    bool outDirGiven = false;
    std::string platform = "osmesa";  // osmesa | egl (--gpu) | glfw (--window)
    fxport::Vector3 cameraPosition = fxport::Vector3(0.0f, 9.0f, 17.0f);
    fxport::Vector3 cameraTarget = fxport::Vector3(0.0f, 1.5f, 0.0f);
    float sampleRadius = 0.25f;
    float distanceScale = 3.0f;
    std::string lights = "dsp";     // which of the seed's lights to keep: directional, spot, point
    bool debugViews = true;         // the seed's Debug() views over the final image
    std::string contentDir;         // empty: FXPORT_CONTENT_DIR
    std::string hlslDir;            // empty: FXPORT_HLSL_DIR
    bool fullSizeImages = false;    // also every debug tile at full size under DIR/targets/
    std::optional<bool> syncPasses; // finish the device around timed passes; default: on for osmesa
    // Game1::DemoSettings' quality/cost knobs (--gbuffer, --spot-shadow, --point-shadow, --no-ssao, --ssao-half).
    Game1::DemoSettings::GBufferFormats gbufferFormats = Game1::DemoSettings::GBufferFormats::Tutorial;
    int spotShadowMapSize = 2048;
    int pointShadowMapSize = 256;
    bool ssao = true;
    bool ssaoHalfResolution = false;
    bool reuseShadowMaps = true;  // --no-shadow-cache: false
    double fillRateGBps = 0;      // --fill-rate (common/pass_bound.h)
    bool bounds = false;          // --bounds (common/pass_bound.h)
    bool explain = false;           // --explain: print what was built and left out (deferred/build_report.h)
    bool checkFinite = false;       // --check-finite: scan every pass's targets for NaN/Inf
    std::vector<std::pair<std::string, std::string>> defines;  // --define NAME=VALUE: every effect's #defines
};

// Returns the process exit code.
int RunDeferred(const RunOptions& options);
// `fxdemo deferred [options]` (registered with FXDEMO_PROGRAM): parses argv (argv[0] is "deferred")
// into RunOptions and runs; 2 on a usage error.
int RunDeferredProgram(int argc, char** argv);

}  // namespace TheCansinDeferredRenderer
