// One row of `fxdemo report`: a demo run with one setting of one knob, its median GPU times and its
// error against the reference image of the same scene.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "fxport/math.h"

namespace fxport::report {

struct ImageError {
    double rms = 0;   // over all pixels and the R, G, B channels, values in [0, 1]
    double max = 0;   // largest channel difference
    double psnr = 0;  // 10 log10(1 / rms^2) dB (peak 1); infinite when rms is 0
};

// `got` and `reference` are RGB, 3 doubles per pixel, the same size. Throws ArgumentError when the
// sizes differ or either holds a NaN.
// `defined`, when given, has one entry per pixel (the values are split evenly among them): pixels
// where it is 0 are left out (the reference has no answer there).
ImageError compareImages(const std::vector<double>& got, const std::vector<double>& reference, const std::string& what,
                         const std::vector<char>* defined = nullptr);

// The back buffer (8-bit) as RGB doubles in [0, 1].
std::vector<double> toRgb(const std::vector<Color>& pixels);

struct Measurement {
    std::string demo;       // "rastertek50", "lighting2d", "pointlights", "deferred"
    std::string knob;       // e.g. "target format"
    std::string setting;    // e.g. "R16G16B16A16_FLOAT"
    bool seedDefault = false;  // the seed's own setting
    // False for a knob that changes the scene itself (pointlights' light count): such a setting is
    // no alternative to the others, so it is left out of the Pareto front.
    bool sameScene = true;
    std::string size;       // "800x600"
    int frames = 0;
    double frameMs = 0;     // median GPU time of the whole frame
    std::vector<std::pair<std::string, double>> passMs;  // median GPU time per pass
    std::vector<double> passBoundMs;  // --bounds: each pass's bound (common/pass_bound.h), as passMs
    std::vector<double> passFillMs;   // --bounds: its two terms (common/pass_estimate.h): fill
    std::vector<double> passFetchMs;  // and texture fetches
    ImageError error;
    std::string reference;  // which reference the error is against
    // A second error where a demo has one: the deferred demo's LightMap target (RGBA, A = specular)
    // against its exact light map (report/deferred_light_map_reference.h), which the shadow-map and
    // G-buffer knobs change; the final image's reference cannot be exact there (SSAO).
    bool hasLightMapError = false;
    ImageError lightMapError;
    // The same, with the shadow terminator's pixels also left out (ExactLightMap::terminator):
    // what the shadow-map knobs can still change.
    ImageError lightMapErrorOffTerminator;
    // The LightMap against the ideal-ESM light map (ExactLightMap::idealEsmRgba): the shadow
    // maps' sampling error alone, which their size does change.
    ImageError lightMapErrorVsIdealEsm;
    std::string lightMapReference;
};

}  // namespace fxport::report
