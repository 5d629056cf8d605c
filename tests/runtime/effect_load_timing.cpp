// Measures loading each effect under hlsl/ eager (EffectOptions::precompile) and lazy, with a cold
// and a warm compile cache, and the first Apply of a lazy effect (which compiles its technique).
// Not a test: prints a table. Run from the repository root:
//   build/tests/runtime/effect_load_timing [REPS]
// Cold = a fresh cache folder; warm = the same folder again. Times include linking the GL programs
// (llvmpipe compiles GLSL to machine code at link), so they are what a host waits.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "runtime_test_support.h"

namespace fs = std::filesystem;
using namespace fxport;

namespace {

using Clock = std::chrono::steady_clock;
double msSince(Clock::time_point t) { return std::chrono::duration<double, std::milli>(Clock::now() - t).count(); }

struct Times {
    double load = 0, firstApply = 0;
};

Times measure(GraphicsDevice& device, const std::string& path, const std::string& cache, bool eager) {
    EffectOptions o;
    o.cacheDir = cache;
    o.precompile = eager;
    Times t;
    auto start = Clock::now();
    Effect effect(device, path, o);
    t.load = msSince(start);
    start = Clock::now();
    effect.CurrentTechnique->Passes[0].Apply();
    t.firstApply = msSince(start);
    return t;
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
    int reps = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
    GraphicsDevice& device = test::testDevice();
    std::vector<std::string> paths;
    for (const auto& e : fs::recursive_directory_iterator("hlsl"))
        if (e.path().extension() == ".fx") paths.push_back(e.path().generic_string());
    std::sort(paths.begin(), paths.end());
    fs::path root = fs::temp_directory_path() / "fxport_effect_load_timing";

    std::printf("median of %d, ms; load = Effect constructor, apply = first Apply (compiles a lazy technique)\n", reps);
    std::printf("%-34s %23s %23s %23s %23s\n", "", "eager cold", "lazy cold", "eager warm", "lazy warm");
    std::printf("%-34s %11s %11s %11s %11s %11s %11s %11s %11s\n", "effect", "load", "apply", "load", "apply", "load",
                "apply", "load", "apply");
    double sums[8] = {};
    for (const std::string& path : paths) {
        std::vector<double> v[8];
        for (int r = 0; r < reps; ++r) {
            fs::remove_all(root);
            std::string eagerCache = (root / "eager").string(), lazyCache = (root / "lazy").string();
            Times ec = measure(device, path, eagerCache, true);
            Times lc = measure(device, path, lazyCache, false);
            Times ew = measure(device, path, eagerCache, true);
            Times lw = measure(device, path, lazyCache, false);
            const Times all[4] = {ec, lc, ew, lw};
            for (int k = 0; k < 4; ++k) {
                v[2 * k].push_back(all[k].load);
                v[2 * k + 1].push_back(all[k].firstApply);
            }
        }
        std::printf("%-34s", path.c_str());
        for (int k = 0; k < 8; ++k) {
            double m = median(v[k]);
            sums[k] += m;
            std::printf(" %11.2f", m);
        }
        std::printf("\n");
    }
    std::printf("%-34s", "total");
    for (double s : sums) std::printf(" %11.2f", s);
    std::printf("\n");
    fs::remove_all(root);
    return 0;
}
