// `fxdemo stability`: the numerical-stability suite (issue 6). Runs stability_cases.h on a headless
// device, prints a table, writes DIR/stability.md and DIR/stability.csv.
//   --size N   targets N x N (default 32)       --gpu   on the GPU (EGL)
//   --no-largest  leave out the driver's widest target (max x 1)
//   --assert   exit 1 unless what must hold holds (ctest): the checker reports float32 overflow of
//              exp(d/2) and normalize(0) as written; the known breakages (near/far 1e7, Rgba64
//              zero normals, a light sphere past the far plane, the spot's cos(FOV) test) show;
//              every fix leaves no NaN/Inf and stays within its bound; unwrap rays match.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "common/program_registry.h"
#include "common/run_options.h"
#include "stability/stability_cases.h"

namespace fxport::stability {

namespace {

int usage(const std::string& message) { return demo::usageError("stability", message); }

std::string firstText(const CaseResult& r) { return r.first ? r.first->describe() : "-"; }

std::string number(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.3g", v);
    return buffer;
}

std::string csvQuoted(const std::string& s) {
    std::string out = "\"";
    for (char c : s) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

void writeCsv(const std::string& path, const std::vector<CaseResult>& results) {
    std::ofstream out(path);
    out << "group,case,variant,pixels,non_finite,saturated,rms_error,max_error,error_kind,first_non_finite\n";
    for (const CaseResult& r : results)
        out << r.group << ',' << csvQuoted(r.name) << ',' << csvQuoted(r.variant) << ',' << r.pixels << ',' << r.nonFinite
            << ',' << r.saturated << ',' << number(r.rmsError) << ',' << number(r.maxError) << ','
            << (r.relative ? "relative" : "absolute") << ',' << csvQuoted(firstText(r)) << '\n';
}

void writeMarkdown(const std::string& path, const std::vector<CaseResult>& results, const std::string& renderer, int size) {
    std::ofstream out(path);
    out << "# fxdemo stability\n\nRenderer: " << renderer << "; targets " << size << "x" << size
        << " unless named. Effects: hlsl/xna-deferred, hlsl/zima-lights (pow00 \"cleared\" and zima-radius rows) and hlsl/lighting2d (unwrap), unchanged. Each row: one run of the real effect, every target "
           "scanned by FiniteCheck, the finite texels compared with a double-precision CPU reference.\n\n"
        << "## Where the tutorial's maths breaks\n\n"
        << "- **Exponential shadow maps** (DepthWriter.fx stores exp(DepthPrecision/2 * d/DepthPrecision) = exp(d/2)): "
           "float16 ends at 65504, reached at d = 22.2; float32 overflows to +Inf at d = 177.4. The seed's shadow "
           "maps are Single (float32), so casters further than ~177 units from a point or spot light write +Inf and the "
           "light pass computes Inf * exp(-d/2) = Inf or Inf * 0 = NaN. Fix offered (host, opt-in): scale the light's "
           "space about the light by k < 1 (World for the depth pass; positions, CameraPosition and LightRadius for "
           "the light pass) so that k d stays under the limit; DepthBias then acts at 1/k the distance.\n"
        << "- **Far from the origin**: float32 positions 1e6 units out are 0.0625 apart; length(LightPosition - "
           "WorldPosition) inherits that error and exp(d/2) multiplies it by d/2. Fix offered (host, opt-in): "
           "light/camera-relative coordinates, the difference taken in double before it becomes a float.\n"
        << "- **pow(0, 0)** on cleared G-buffer pixels (Clear.fx writes specular power 0): PointLight.fx computes "
           "SpecularIntensity * pow(saturate(dot(R, E)), SpecularPower); where R faces away from the eye that is "
           "0 * pow(0, 0): undefined in GLSL, NaN wherever a driver evaluates exp2(y log2 x) literally (0 * -Inf); "
           "the pow00 rows show what this driver does. Where it is NaN, the demo's Color light map stores it as 0, so "
           "it is invisible there; a float light map keeps it. Fix offered (runtime, opt-in, no edit of the effect): compile with the define "
           "`pow(x, y)` = `pow(max(x, 1e-30), y)` (EffectOptions::defines). Catalin Zima's PointLight.fx and "
           "SpotLight.fx (fxdemo pointlights) have the same term; their rows are named \"cleared, point/spot\". In "
           "fxdemo pointlights the light volumes of lights near the walls cover background pixels; with the "
           "tutorial's Color lightRT, GL clamps the blend's source to [0, 1], which takes a NaN to 0 in practice; the "
           "half16/float32 light maps (--gbuffer) keep it.\n"
        << "- **Near/far ratio** (GBuffer.fx stores z/w = f/(f-n) (1 - n/D)): z/w crowds against 1, where float32 "
           "resolves 6e-8, so the distance PointLight.fx reconstructs moves in steps of ~D^2/n * 6e-8 (near-far rows: "
           "1e-6 D at f/n = 1e2, 6e-2 D at 1e7). Fix offered (host, opt-in): a reversed-Z projection (M33 = n/(f-n), "
           "M43 = n f/(f-n); depth test GreaterEqual, depth cleared to 0): z/w ~ n/D keeps float32's relative "
           "precision (5e-7 D at every ratio); the light passes invert whatever projection they get.\n"
        << "- **Zero-length and denormal normals** (GBuffer.fx normalizes the vertex normal, then the mapped normal): "
           "normalize(0) = 0 * inversesqrt(0) = NaN; a 1e-20 normal squares to an underflow, a denormal one is flushed: "
           "NaN too. A float normals target keeps the NaN (the light is NaN); the tutorial's Rgba64 stores it as 0, "
           "which decodes to (-1, -1, -1): finite, wrong, invisible to FiniteCheck. Fix offered (runtime, opt-in): "
           "GBuffer.fx compiled with `normalize(v)` defined to scale by the largest component first and keep 0 as 0 "
           "(a zero normal then gets no diffuse light).\n"
        << "- **Camera inside a point light's volume larger than the far plane**: the inner faces of the light's "
           "sphere (the demos' cull switch) are all clipped, and the light vanishes. Fix offered (host): draw the "
           "light as a full-screen quad when the camera is inside. Radius 0 and 1e-6 are harmless (1 - Inf saturates "
           "to 0; max(.01) avoids 0/0). Zima's lights divide by the radius without a guard: radius 0 gives "
           "saturate(1 - |L| / 0) = 0 on IEEE hardware (zima-radius rows).\n"
        << "- **Spot cone test** (SpotLight.fx: lit where dot(L, S) <= LightAngleCos, the demo passes cos(FOV)): L points "
           "at the light, so the test admits angle(-L, S) <= 180 - FOV, not FOV/2. Right only with the seed's 90 degrees "
           "and its cookie; below 90 it lights pixels behind the light, above 120 it narrows the cone (179.9: only the "
           "axis). Fix offered (host): LightAngleCos = -cos(FOV/2).\n"
        << "- **Unwrap rays with sin or cos exactly 0** are fine: theta = 0 takes the effects' guard, and no other float "
           "angle has an exact zero (cos(float(pi/2)) = -4.4e-8), so those rays take the general branch, whose 1e7-size "
           "exits the min() discards. Only a light exactly on the caster texture's edge differs from the exact ray "
           "(distance 0 instead of the distance along the edge): the float ray leaves the texture at once.\n\n"
        << "## Results\n\n"
        << "| group | case | variant | pixels | non-finite | saturated | RMS error | max error | first NaN/Inf |\n"
        << "|---|---|---|---:|---:|---:|---:|---:|---|\n";
    for (const CaseResult& r : results)
        out << "| " << r.group << " | " << r.name << " | " << r.variant << " | " << r.pixels << " | " << r.nonFinite << " | "
            << r.saturated << " | " << number(r.rmsError) << " | " << number(r.maxError) << (r.relative ? " rel" : " abs")
            << " | " << firstText(r) << " |\n";
    out << "\nNotes per case:\n\n";
    for (const CaseResult& r : results) out << "- " << r.group << " / " << r.name << " / " << r.variant << ": " << r.note << "\n";
    out << "\nNot covered by this suite yet (issue 6 list): Catalin Zima's lights beyond pow(0, 0) and radius 0 (the "
           "other cases run xna-deferred's; Zima's spot test SdL > cos(angle) is the correct half-angle form), DirectionalLight.fx's "
           "reconstruction (it sets Position.y from UV.x, as written), a surface point exactly at a light "
           "(normalize(0) of the light vector), and the driver's largest square target (only max x 1 runs). "
           "Matrix::Invert of singular/near-singular matrices is pinned in tests/runtime/matrix_invert_test.cpp.\n";
}

// What must hold for the groups of issue 6's second list. Bounds: 5e-5 where the GPU evaluates the
// same float32 formula as the double reference (observed <= 3e-6 on llvmpipe, 2.5e-5 on an H100,
// whose pow/rsqrt are approximations D3D and GL allow); 1e-4 where an Rgba64 normal (1.5e-5 steps
// per component) feeds the light. Unwrap rays whose sin or cos is only nearly 0 (float pi/2, pi)
// from a light ON the texture's edge are reported, not asserted: the answer turns on the sign of a
// 4e-8 sine, which a GPU's approximate sin/cos need not keep (an H100 took the other side).
const double kGpuFloat = 5e-5;

void checkNewGroups(const std::vector<CaseResult>& results,
                    const std::function<void(const CaseResult&, const std::string&)>& fail,
                    std::vector<std::string>& failures) {
    auto clean = [&](const CaseResult& r, double bound) {
        if (r.nonFinite != 0) fail(r, "non-finite texels: " + firstText(r));
        if (r.pixels == 0) fail(r, "no pixel compared");
        if (!(r.maxError <= bound)) fail(r, "max error " + number(r.maxError) + " above " + number(bound));
    };
    auto broken = [&](const CaseResult& r, double above, const char* what) {
        if (!(r.maxError > above)) fail(r, std::string("expected ") + what + " (error above " + number(above) + "), got " + number(r.maxError));
    };
    int seen = 0;
    for (const CaseResult& r : results) {
        const bool fixed = r.variant != "as written";
        auto named = [&](const char* s) { return r.name.find(s) != std::string::npos; };
        if (r.group == "near-far") {
            ++seen;
            const int exponent = std::atoi(r.name.c_str() + r.name.find("1e") + 2);
            const double D = 0.05 * std::pow(10.0, exponent);  // f/2, n = 0.1
            if (fixed) clean(r, kGpuFloat * D);
            else if (exponent == 7) broken(r, 1e-3 * D, "float32 z/w to lose the distance at f/n = 1e7");
        } else if (r.group == "normals") {
            ++seen;
            const bool rgba64 = named("Rgba64");
            if (fixed || named("unit")) clean(r, rgba64 ? 1e-4 : kGpuFloat);
            else if (!rgba64) {
                if (r.nonFinite == 0 || !r.first || r.first->pass != "GBuffer")
                    fail(r, "normalize(0) NaN not reported in pass GBuffer: " + firstText(r));
            } else broken(r, 0.5, "NaN stored as 0 in Rgba64 to light with (-1, -1, -1)");
        } else if (r.group == "point-light") {
            ++seen;
            const bool sphere = r.variant.rfind("sphere", 0) == 0;
            if (sphere && (r.variant.find("no switch") != std::string::npos || named("r=1e+06")))
                broken(r, 0.4, "the sphere to leave the light out");
            else clean(r, kGpuFloat);
        } else if (r.group == "spot-cone") {
            ++seen;
            if (fixed) clean(r, kGpuFloat);
            else if (named("FOV 0.1") || named("FOV 179.9") || named("facing away"))
                broken(r, 0.1, "cos(FOV) as the cone test to light the wrong pixels");
        } else if (r.group == "zima-radius") {
            ++seen;
            clean(r, 0.0);  // saturate(1 - |L| / 0) = 0 exactly
        } else if (r.group == "unwrap") {
            ++seen;
            const bool nearZeroOnEdge = named("~0") && (named("light x=0") || named("light y=0"));
            if (!nearZeroOnEdge) clean(r, 1e-6);
        }
    }
    if (seen == 0) failures.push_back("none of the near-far/normals/point-light/spot-cone/unwrap cases ran");
}

// What must hold; returns the failures.
std::vector<std::string> checkExpectations(const std::vector<CaseResult>& results) {
    std::vector<std::string> failures;
    auto fail = [&](const CaseResult& r, const std::string& why) {
        failures.push_back(r.group + " / " + r.name + " / " + r.variant + ": " + why);
    };
    bool sawOverflow = false;
    for (const CaseResult& r : results) {
        const bool fixed = r.variant != "as written";
        if (r.group == "exp-shadow" && !fixed && r.name.find("Single") != std::string::npos &&
            (r.name.rfind("d=180", 0) == 0 || r.name.rfind("d=400", 0) == 0)) {
            // exp(90) and exp(200) overflow float32 on every IEEE GPU: the checker must say so.
            sawOverflow = true;
            if (r.nonFinite == 0 || !r.first) fail(r, "float32 overflow of exp(d/2) was not reported by FiniteCheck");
            else if (r.first->pass != "DepthWriter" || r.first->target.find("shadowMap") != 0)
                fail(r, "reported, but not as pass DepthWriter / shadowMap: " + r.first->describe());
        }
        const bool firstList = r.group == "exp-shadow" || r.group == "far-from-origin" || r.group == "target-size" ||
                               r.group == "pow00";  // the others: checkNewGroups
        if (firstList && (fixed || r.group == "target-size" || (r.group == "exp-shadow" && r.name.rfind("d=10 ", 0) == 0))) {
            if (r.nonFinite != 0) fail(r, "non-finite texels: " + firstText(r));
            if (r.saturated != 0) fail(r, std::to_string(r.saturated) + " texels saturated");
            if (r.pixels == 0) fail(r, "no pixel compared");
            const double bound = r.group == "pow00" ? 0.0 : 2e-3;  // half: 2^-11 relative steps
            if (!(r.maxError <= bound)) fail(r, "max error " + number(r.maxError) + " above " + number(bound));
        }
        if (r.group == "far-from-origin" && !fixed && r.name == "t=1e6" && !(r.maxError > 1e-3))
            fail(r, "expected the as-written error at 1e6 to exceed 1e-3 (float32 spacing 0.0625), got " + number(r.maxError));
    }
    if (!sawOverflow) failures.push_back("no float32 overflow case ran");
    checkNewGroups(results, fail, failures);
    return failures;
}

}  // namespace

int runStability(int argc, char** argv) {
    demo::CommonOptions common;
    common.outDir = "fxdemo-out/stability";
    common.width = common.height = 32;
    SuiteOptions options;
    options.hlslDir = FXPORT_HLSL_DIR;
    bool assertMode = false;
    for (int i = 1; i < argc; ++i) {
        const std::string arg = argv[i];
        std::string error;
        if (arg == "--size" && i + 1 < argc && std::string(argv[i + 1]).find('x') == std::string::npos) {
            const char* v = argv[++i];
            char* end = nullptr;
            const long n = std::strtol(v, &end, 10);
            if (end == v || *end || n <= 0 || n > 4096) return usage(demo::wants("--size", "N (or NxN) in 1..4096", v));
            options.size = int(n);
            continue;
        }
        demo::OptionResult parsed = demo::parseCommonOption(argc, argv, i, common, error);
        if (parsed == demo::OptionResult::Error) return usage(error);
        if (parsed == demo::OptionResult::Consumed) continue;
        if (arg == "--assert") assertMode = true;
        else if (arg == "--no-largest") options.largest = false;
        else if (arg == "--hlsl") {
            if (i + 1 >= argc) return usage(demo::wants("--hlsl", "a folder", nullptr));
            options.hlslDir = argv[++i];
        } else return usage(demo::unknownOption("stability", arg));
    }
    if (common.width != 32 || common.height != 32) {  // --size WxH: W
        if (common.width > 4096) {
            const std::string size = std::to_string(common.width) + "x" + std::to_string(common.height);
            return usage(demo::wants("--size", "N (or NxN) in 1..4096", size.c_str()));
        }
        options.size = common.width;
    }
    if (common.platform == "glfw") return usage("--window: the suite runs headless only (--gpu for EGL); leave it out");
    if (!common.defines.empty()) return usage("--define: each case picks its own defines (as written and fixed)");

    PresentationParameters parameters;
    parameters.BackBufferWidth = parameters.BackBufferHeight = 16;
    parameters.platform = common.platform;
    GraphicsDevice device(parameters);
    std::printf("fxdemo stability: %dx%d targets on %s (%s)\n", options.size, options.size, common.platform.c_str(),
                device.rendererName().c_str());
    const std::vector<CaseResult> results = runStabilityCases(device, options);

    std::printf("%-16s %-26s %-38s %7s %9s %6s %10s %10s  %s\n", "group", "case", "variant", "pixels", "nonfinite", "sat",
                "rms err", "max err", "first NaN/Inf");
    for (const CaseResult& r : results)
        std::printf("%-16s %-26s %-38s %7d %9lld %6lld %10.3g %10.3g  %s\n", r.group.c_str(), r.name.c_str(),
                    r.variant.c_str(), r.pixels, (long long)r.nonFinite, (long long)r.saturated, r.rmsError, r.maxError,
                    firstText(r).c_str());

    std::filesystem::create_directories(common.outDir);
    const std::string md = (std::filesystem::path(common.outDir) / "stability.md").string();
    const std::string csv = (std::filesystem::path(common.outDir) / "stability.csv").string();
    writeMarkdown(md, results, device.rendererName(), options.size);
    writeCsv(csv, results);
    std::printf("wrote %s and %s\n", md.c_str(), csv.c_str());

    if (!assertMode) return 0;
    const std::vector<std::string> failures = checkExpectations(results);
    for (const std::string& f : failures) std::fprintf(stderr, "stability: FAILED %s\n", f.c_str());
    if (failures.empty()) std::printf("stability: all expectations hold\n");
    return failures.empty() ? 0 : 1;
}

}  // namespace fxport::stability

FXDEMO_PROGRAM(stability,
               "fxdemo stability [--size N] [--out DIR] [--gpu] [--no-largest] [--assert] [--hlsl DIR]\n"
               "  Stiff and extreme inputs through the real effects: NaN/Inf scans and CPU references per case.\n"
               "  --size N       the cases' target size, 1..4096 (32)\n"
               "  --out DIR      where the table and images go (fxdemo-out/stability)\n"
               "  --gpu          headless on the GPU (EGL) instead of OSMesa\n"
               "  --no-largest   leave out the driver's widest target (GL_MAX_TEXTURE_SIZE x 1)\n"
               "  --assert       exit 1 unless the known breakages show and every opt-in fix holds\n"
               "  --hlsl DIR     the effects' folder (the source tree's hlsl/)",
               fxport::stability::runStability);
