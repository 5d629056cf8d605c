// Rastertek tutorial 50 (seed 004): the G-buffer targets' format. Reference: the CPU rasteriser
// and shading of rastertek50/reference_check (exact normals, trilinear texture, double).
#include <memory>
#include <stdexcept>

#include "rastertek50/applicationclass.h"
#include "rastertek50/reference_check.h"
#include "report/sweep.h"

namespace fxport::report {

std::vector<Measurement> sweepRastertek50(const SweepOptions& options) {
    struct Setting {
        d3d11::DXGI_FORMAT format;
        const char* name;
    };
    const std::vector<Setting> settings = {{d3d11::DXGI_FORMAT_R32G32B32A32_FLOAT, "R32G32B32A32_FLOAT"},
                                           {d3d11::DXGI_FORMAT_R16G16B16A16_FLOAT, "R16G16B16A16_FLOAT"},
                                           {d3d11::DXGI_FORMAT_R8G8B8A8_UNORM, "R8G8B8A8_UNORM"}};
    // Even sizes: the seed's ortho window maps pixel (x, y) to G-buffer texel (x, y) only then.
    const int width = options.width ? options.width & ~1 : 800, height = options.height ? options.height & ~1 : 600;
    std::vector<Measurement> out;
    for (const Setting& s : settings) {
        Rastertek50::ApplicationClass application;
        application.SetGBufferFormat(s.format);
        // The headless demo's last frame (25 frames of pi/100: 45 degrees), whatever the number of
        // warm-up and timed frames; before this, each setting was measured at another angle.
        application.SetFixedRotation(25 * float(3.14159265358979) * 0.01f);
        if (!application.Initialize(options.platform, FXPORT_HLSL_DIR, width, height))
            throw std::runtime_error("rastertek50: Initialize failed");
        GraphicsDevice& device = application.GetD3D()->GetCoreDevice();
        auto timer = std::make_unique<GpuTimer>(device);
        application.SetGpuTimer(timer.get());
        Measurement m;
        m.demo = "rastertek50";
        m.knob = "target format";
        m.setting = s.name;
        m.seedDefault = s.format == d3d11::DXGI_FORMAT_R32G32B32A32_FLOAT;
        m.reference = "CPU raster + shading (exact)";
        runTimedFrames(device, *timer, options, [&] { application.Frame(); }, m);
        const std::vector<double> reference = Rastertek50::ReferenceImage(application);
        const std::vector<Color> back = application.GetD3D()->GetBackBufferData();
        m.error = compareImages(toRgb(back), reference, "rastertek50 " + m.setting);
        if (out.empty()) saveReference(device, options, m.demo, reference, width, height);
        saveImage(device, options, m, back, width, height);
        application.SetGpuTimer(nullptr);
        timer.reset();
        application.Shutdown();
        out.push_back(m);
        if (options.progress) options.progress(m);
    }
    return out;
}

}  // namespace fxport::report
