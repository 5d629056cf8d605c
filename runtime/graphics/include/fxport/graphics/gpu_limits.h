// GpuLimits: what this GPU can do at most, measured once per device and cached (issue 16): the
// fragment output rate of each render-target format with blending off and additive, the clear
// rate, the bilinear texture fetch rate, and the rate a compute shader writes an image. A pass's bound -- the time the GPU needs just to
// write the fragments the pass wrote, at this rate -- says how far the pass is from the GPU's limit
// (fxdemo's timing tables, --explain and `fxdemo report` print pass, ms, bound ms, ratio).
//
//   GpuLimits limits = GpuLimits::ForDevice(device);  // measured, or read from the cache
//   double ms = fragments * bytesPerPixel(format) / (limits.fillGBps(format, blended) * 1e6);
#pragma once

#include <string>
#include <vector>

#include "fxport/graphics/surface_format.h"

namespace fxport {

class GraphicsDevice;

struct GpuLimits {
    struct Fill {
        SurfaceFormat format;
        double opaqueGBps = 0;   // bytes of fragment output per second / 1e9, blending off
        double blendedGBps = 0;  // with additive blending (one read + one write per fragment)
    };
    std::string renderer;            // the GL renderer string the numbers belong to
    std::vector<Fill> fill;          // Color, Rgba64, HalfVector4, Vector4, Single, Vector2
    double clearGBps = 0;            // glClear of a Color target
    double fetchGTexelsPerSecond = 0;  // bilinear fetches of a Color texture in a pixel shader
    double computeWriteGBps = 0;     // imageStore of a Color (rgba8) image from a compute shader, 8x8
                                     // work groups, one dispatch per pass (DeviceOptimizations::ComputePasses)

    // The rate of `format` (a format not measured: the measured one of the same texel size, else
    // the slowest measured); 0 when nothing was measured.
    double fillGBps(SurfaceFormat format, bool blended) const;

    // Draws full-screen triangles into size x size targets `repeats` times per measurement and
    // times them with GL timer queries. Leaves the device's GL state as it found it.
    static GpuLimits Measure(GraphicsDevice& device, int size = 2048, int repeats = 20);
    // The cached measurement of this renderer from `cacheDir` (empty: $FXPORT_CACHE_DIR, else
    // $XDG_CACHE_HOME/fxport, else ~/.cache/fxport -- the effect cache's folder), measured and
    // written there the first time.
    static GpuLimits ForDevice(GraphicsDevice& device, const std::string& cacheDir = {});

    // Whether `renderer` (a GL renderer string) is a software rasteriser: llvmpipe, softpipe,
    // SwiftShader, swrast.
    static bool softwareRenderer(const std::string& renderer);

    // Whether compute images are written at least kComputePassesWhereFaster times as fast as the
    // fragment stage writes a Color target: DeviceOptimizations::ComputePasses' default.
    bool computePassesFaster() const;

    std::string toText() const;  // one "key value" line each (the cache file)
    static bool fromText(const std::string& text, GpuLimits& out);
};

}  // namespace fxport
