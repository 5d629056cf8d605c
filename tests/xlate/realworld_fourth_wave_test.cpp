// Real-world shaders, fourth wave (session 22's run over D3D11 samples: Intel ASSAO, NVIDIA
// D3DSamples, Microsoft Xbox-ATG-Samples, GameTechDev's OutdoorLightScattering): valid HLSL that fxc
// compiles and fxport refused. Each is a small source of our own in the sample's shape, compiled as
// the sample's build does, with what the construct means asserted on the reflection or the GLSL.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

namespace {

fs::path writeSource(const std::string& name, const std::string& source) {
    fs::path dir = fs::temp_directory_path() / ("fxport-fourth-wave-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / name) << source;
    return dir / name;
}

CompiledEffect compileLoose(const std::string& source, const std::string& profile, const std::string& entry = "main") {
    CompileOptions o;
    o.useCache = false;
    return compileShaderFiles({{writeSource("shader.hlsl", source).string(), entry, profile}}, o);
}

}  // namespace

// ASSAO's vaSimpleShadowMap.hlsl: two functions each size a flat-initialised array by their own
// `const int sampleCount` (6 and 14). Each array takes its own function's constant.
TEST(RealworldFourthWave, LocalConstantSizesAreTheirFunctions) {
    CompiledEffect e = compileLoose(
        "float2 a() { const int n = 3; const float2 o[n] = {1, 2, 3, 4, 5, 6}; return o[n - 1]; }\n"
        "float2 b() { const int n = 4; const float2 o[n] = {1, 2, 3, 4, 5, 6, 7, 8}; return o[n - 1]; }\n"
        "float4 main() : SV_Target { return float4(a(), b()); }\n",
        "ps_5_0");
    EXPECT_FALSE(e.shaders.at(0).glsl.empty());
}
