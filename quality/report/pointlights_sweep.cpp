// Catalin Zima's point lights (seed 001): number of lights, light-volume tessellation, G-buffer
// formats. Reference: the light pass evaluated on the CPU in double precision (DirectionalLight.fx
// and PointLight.fx, the conventions of pointlights/reference_check), without a light volume (every
// pixel within a light's radius is lit) and without clamping, on the G-buffer of the same frame
// rendered in float32 (Vector4 / Vector4 / Single), then CombineFinal.fx; so the error is what the
// formats, the 8-bit light map's clamp and the volume's tessellation cost.
#include <algorithm>
#include <cmath>
#include <memory>

#include "pointlights/game1.h"
#include "report/sweep.h"

namespace fxport::report {

namespace {

using DeferredLighting::DeferredRenderer;
using DeferredLighting::Game1;

struct GBuffer {
    int W = 0, H = 0;
    std::vector<Vector4> color, normal;
    std::vector<float> depth;
};

struct D3 {
    double x, y, z;
};
D3 operator-(D3 a, D3 b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
D3 operator*(D3 a, double s) { return {a.x * s, a.y * s, a.z * s}; }
double dot(D3 a, D3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
D3 normalize(D3 a) { return a * (1.0 / std::sqrt(dot(a, a))); }
D3 d3(Vector3 v) { return {v.X, v.Y, v.Z}; }
D3 reflect(D3 i, D3 n) { return i - n * (2 * dot(n, i)); }
double saturate(double v) { return std::clamp(v, 0.0, 1.0); }

// The final image the game's last frame should have given `g` (see the top of this file).
std::vector<double> referenceImage(Game1& game, const GBuffer& g) {
    DeferredRenderer& r = game.getRenderer();
    DeferredLighting::Camera& camera = game.getCamera();
    const int W = g.W, H = g.H;
    const Matrix ivp = Matrix::Invert(camera.View * camera.Projection);
    const D3 cam = d3(camera.Position);
    auto toWorld = [&](double nx, double ny, double nz) {
        const double x = nx * ivp.M11 + ny * ivp.M21 + nz * ivp.M31 + ivp.M41;
        const double y = nx * ivp.M12 + ny * ivp.M22 + nz * ivp.M32 + ivp.M42;
        const double z = nx * ivp.M13 + ny * ivp.M23 + nz * ivp.M33 + ivp.M43;
        const double w = nx * ivp.M14 + ny * ivp.M24 + nz * ivp.M34 + ivp.M44;
        return D3{x / w, y / w, z / w};
    };
    struct L {
        D3 p, c;
        double radius, radius2, intensity;
    };
    std::vector<L> lights;
    for (const auto& l : r.drawnPointLights)
        lights.push_back({d3(l.position), d3(l.color), l.radius, double(l.radius) * l.radius, l.intensity});
    const D3 dirLight = normalize(d3(r.drawnDirection)) * -1.0, dirColor = d3(r.drawnDirectionalColor);

    // lightRT at pixel (x, y): D3D9 centres, G-buffer texel (x-1, y-1) (pointlights/reference_check).
    std::vector<double> light(std::size_t(W) * std::size_t(H) * 4, 0.0);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const std::size_t t = std::size_t(std::max(0, y - 1)) * std::size_t(W) + std::size_t(std::max(0, x - 1));
            const Vector4 nv = g.normal[t];
            const D3 n = {2.0 * nv.X - 1, 2.0 * nv.Y - 1, 2.0 * nv.Z - 1};
            const double specularPower = nv.W * 255.0, specularIntensity = g.color[t].W;
            double* sum = &light[(std::size_t(y) * std::size_t(W) + std::size_t(x)) * 4];
            {
                const D3 position = toWorld(2.0 * ((x - 0.5) / W) - 1, -(2.0 * ((y - 0.5) / H) - 1), g.depth[t]);
                const double NdL = std::max(0.0, dot(n, dirLight));
                const D3 reflection = normalize(reflect(dirLight, n));
                const double spec = specularIntensity * std::pow(saturate(dot(reflection, normalize(cam - position))), specularPower);
                sum[0] += NdL * dirColor.x, sum[1] += NdL * dirColor.y, sum[2] += NdL * dirColor.z, sum[3] += spec;
            }
            const D3 position = toWorld(2.0 * x / W - 1, 1 - 2.0 * y / H, g.depth[t]);
            const D3 toCamera = normalize(cam - position);
            for (const L& l : lights) {
                D3 v = l.p - position;
                const double d2 = dot(v, v);
                if (d2 >= l.radius2) continue;
                const double attenuation = (1.0 - std::sqrt(d2) / l.radius) * l.intensity;
                v = normalize(v);
                const double NdL = std::max(0.0, dot(n, v));
                const D3 reflection = normalize(reflect(v * -1.0, n));
                const double spec = specularIntensity * std::pow(saturate(dot(reflection, toCamera)), specularPower);
                sum[0] += attenuation * NdL * l.c.x, sum[1] += attenuation * NdL * l.c.y;
                sum[2] += attenuation * NdL * l.c.z, sum[3] += attenuation * spec;
            }
        }
    // CombineFinal.fx: texCoord - halfPixel is the centre of texel (x-1, y-1) of both maps.
    std::vector<double> rgb(std::size_t(W) * std::size_t(H) * 3);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const std::size_t t = std::size_t(std::max(0, y - 1)) * std::size_t(W) + std::size_t(std::max(0, x - 1));
            const Vector4 c = g.color[t];
            const double* l = &light[t * 4];
            double* o = &rgb[(std::size_t(y) * std::size_t(W) + std::size_t(x)) * 3];
            o[0] = saturate(c.X * l[0] + l[3]), o[1] = saturate(c.Y * l[1] + l[3]), o[2] = saturate(c.Z * l[2] + l[3]);
        }
    return rgb;
}

std::unique_ptr<Game1> startGame(const SweepOptions& options, int width, int height, const DeferredRenderer::Quality& q) {
    auto game = std::make_unique<Game1>();
    game->graphics.PreferredBackBufferWidth = width;
    game->graphics.PreferredBackBufferHeight = height;
    game->graphics.platform = options.platform;
    game->demo.time = 1.0;  // the demo's reproducible headless frame
    game->demo.quality = q;
    game->Start();
    return game;
}

const char* formatsName(DeferredRenderer::GBufferFormats f) {
    switch (f) {
    case DeferredRenderer::GBufferFormats::Tutorial: return "Color/Color/Single, light Color";
    case DeferredRenderer::GBufferFormats::Half16: return "HalfVector4 x2/HalfSingle, light HalfVector4";
    case DeferredRenderer::GBufferFormats::Float32: return "Vector4 x2/Single, light Vector4";
    }
    return "?";
}

}  // namespace

std::vector<Measurement> sweepPointLights(const SweepOptions& options) {
    const int width = options.width ? options.width : 640, height = options.height ? options.height : 480;
    // The reference G-buffer: one frame in float32 (it does not depend on the lights).
    GBuffer g;
    {
        DeferredRenderer::Quality q;
        q.gbufferFormats = DeferredRenderer::GBufferFormats::Float32;
        auto game = startGame(options, width, height, q);
        game->Tick();
        DeferredRenderer& r = game->getRenderer();
        g.W = width, g.H = height;
        g.color = r.getColorRT().GetData<Vector4>();
        g.normal = r.getNormalRT().GetData<Vector4>();
        g.depth = r.getDepthRT().GetData<float>();
    }
    struct Setting {
        std::string knob, setting;
        DeferredRenderer::Quality q;
        bool seed;
    };
    std::vector<Setting> settings;
    using F = DeferredRenderer::GBufferFormats;
    const std::vector<int> counts = options.quick ? std::vector<int>{1, 10} : std::vector<int>{1, 10, 100, 1000, 10000};
    settings.push_back({"light count", "22 (the chapter's)", {}, true});
    for (int n : counts) settings.push_back({"light count", std::to_string(n), {F::Tutorial, n, 0}, false});
    const std::vector<int> segments = options.quick ? std::vector<int>{4, 16} : std::vector<int>{4, 6, 8, 12, 16, 24, 48, 64};
    for (int s : segments)
        settings.push_back({"sphere tessellation", std::to_string(s) + "x" + std::to_string(std::max(2, s / 2)), {F::Tutorial, 0, s}, false});
    settings.push_back({"sphere tessellation", "32x16 (PointLightGeometry)", {}, true});
    for (F f : {F::Tutorial, F::Half16, F::Float32}) settings.push_back({"G-buffer formats", formatsName(f), {f, 0, 0}, f == F::Tutorial});

    std::vector<Measurement> out;
    for (const Setting& s : settings) {
        auto game = startGame(options, width, height, s.q);
        auto timer = std::make_unique<GpuTimer>(*game->GraphicsDevice);
        game->getRenderer().setGpuTimer(timer.get());
        Measurement m;
        m.demo = "pointlights";
        m.knob = s.knob;
        m.setting = s.setting;
        m.seedDefault = s.seed;
        m.sameScene = !(s.knob == "light count" && !s.seed);
        m.reference = "CPU light pass (exact volumes, unclamped) on the float32 G-buffer";
        runTimedFrames(*game->GraphicsDevice, *timer, options, [&] { game->Tick(); }, m);
        const std::vector<double> reference = referenceImage(*game, g);
        m.error = compareImages(toRgb(game->GraphicsDevice->GetBackBufferData()), reference,
                                "pointlights " + s.knob + " " + s.setting);
        if (out.empty()) saveReference(*game->GraphicsDevice, options, m.demo, reference, width, height);
        saveImage(*game->GraphicsDevice, options, m);
        game->getRenderer().setGpuTimer(nullptr);
        timer.reset();
        out.push_back(m);
        if (options.progress) options.progress(m);
    }
    return out;
}

}  // namespace fxport::report
