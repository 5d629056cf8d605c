// What every knob sweep of `fxdemo report` shares: the run options, the timed frames, and one
// function per demo that runs its settings and returns one Measurement each.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "fxport/graphics.h"
#include "report/measurement.h"

namespace fxport::report {

struct SweepOptions {
    std::string platform = "osmesa";  // or "egl" (--gpu)
    int frames = 3;                   // timed frames per setting
    int warmupFrames = 1;             // run first, not timed (GPU clocks, first use of programs)
    double warmupSeconds = 0;         // ... and for at least this long (a GPU's clocks ramp up slowly)
    bool quick = false;               // few settings at a tiny size (ctest)
    int width = 0, height = 0;        // 0: each demo's own default size
    std::string outDir;               // where the per-setting images go (empty: none)
    bool bounds = false;              // --bounds: each pass's bound beside its time (PassBound)
    std::function<void(const Measurement&)> progress;  // called after each setting
};

// Runs 1 + `frames` frames with `timer` attached (the first is not counted) (PassTimer syncs the device around each pass on
// OSMesa, as the demos do), then fills frameMs and passMs of `m`.
void runTimedFrames(GraphicsDevice& device, GpuTimer& timer, const SweepOptions& options,
                    const std::function<void()>& frame, Measurement& m);

// Writes the back buffer to outDir/<demo>/<knob>-<setting>.png when outDir is set.
void saveImage(GraphicsDevice& device, const SweepOptions& options, const Measurement& m);
// The same for a port that renders through a D3D front end: its back buffer read back (`pixels`,
// W x H, top row first), encoded by a Texture2D of `device`.
void saveImage(GraphicsDevice& device, const SweepOptions& options, const Measurement& m, const std::vector<Color>& pixels,
               int width, int height);

// Writes `rgb` (W x H x 3 in [0, 1]) to outDir/images/<demo>/<name> when outDir is set.
void saveReference(GraphicsDevice& device, const SweepOptions& options, const std::string& demo,
                   const std::vector<double>& rgb, int width, int height, const std::string& name = "reference.png");

std::vector<Measurement> sweepRastertek50(const SweepOptions& options);
std::vector<Measurement> sweepLighting2d(const SweepOptions& options);
std::vector<Measurement> sweepPointLights(const SweepOptions& options);
std::vector<Measurement> sweepDeferred(const SweepOptions& options);

}  // namespace fxport::report
