// fxdemo stability: stiff and extreme inputs run through the real effects of hlsl/ (xna-deferred
// mostly; zima-lights and lighting2d where theirs differ), unchanged, each result scanned by
// FiniteCheck and compared with a double-precision CPU reference of the same maths. A case runs once as the tutorial does it ("as written") and, where
// the tutorial's maths breaks, once more with an opt-in fix chosen by the host (no effect edited).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fxport/graphics.h"

namespace fxport::stability {

struct CaseResult {
    std::string group;        // "exp-shadow", "far-from-origin", "pow00", "target-size", "near-far", ...
    std::string name;         // "d=180 Single"
    std::string variant;      // "as written" or the fix, e.g. "light space x0.1"
    int pixels = 0;           // pixels compared with the reference
    std::int64_t nonFinite = 0;   // texels FiniteCheck found NaN/Inf in (all passes)
    std::optional<NonFiniteTarget> first;  // the first pass/target/pixel that produced one
    std::int64_t saturated = 0;   // finite texels stuck at the format's largest value (65504, FLT_MAX)
    double rmsError = 0, maxError = 0;  // against the reference (relative where `relative`), finite texels only
    bool relative = true;
    std::string note;         // what the numbers mean for this case
};

struct SuiteOptions {
    int size = 32;            // targets are size x size (the 1x1 and widest cases aside)
    std::string hlslDir;      // hlsl/ root
    bool largest = true;      // also the driver's widest target (max x 1)
};

// Runs every case on `device`; each case names its passes for FiniteCheck.
std::vector<CaseResult> runStabilityCases(GraphicsDevice& device, const SuiteOptions& options);

// The case groups, each in its own file (appending to `results`):
// near/far ratios 1e2..1e7 through GBuffer.fx depth and PointLight.fx's reconstruction.
void runDepthRangeCases(GraphicsDevice& device, const SuiteOptions& options, std::vector<CaseResult>& results);
// zero-length, denormal and tiny vertex normals through GBuffer.fx into a lit pixel.
void runNormalCases(GraphicsDevice& device, const SuiteOptions& options, std::vector<CaseResult>& results);
// point light radius -> 0 and -> 1e6 on lit pixels; the camera at the light, inside its volume.
void runPointLightCases(GraphicsDevice& device, const SuiteOptions& options, std::vector<CaseResult>& results);
// spot cone angles near 0 and 180 degrees (xna-deferred SpotLight.fx).
void runSpotConeCases(GraphicsDevice& device, const SuiteOptions& options, std::vector<CaseResult>& results);
// Zima's PointLight.fx / SpotLight.fx (fxdemo pointlights): pow(0, 0) on cleared pixels, radius 0.
void runZimaLightCases(GraphicsDevice& device, const SuiteOptions& options, std::vector<CaseResult>& results);
// lighting2d unwrap rays with sin or cos exactly 0 (Unwrap.fx, UnwrapSpotlight.fx).
void runUnwrapCases(GraphicsDevice& device, const SuiteOptions& options, std::vector<CaseResult>& results);

}  // namespace fxport::stability
