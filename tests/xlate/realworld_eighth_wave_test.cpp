// Real-world shaders, eighth wave (session 26's run 27 over OpenXRay's r5 shaders, Torque3D, AMD's
// ShadowFX / GeometryFX / DepthOfFieldFX, Intel's CloudsGPUPro6 and DeferredCoarsePixelShading,
// Nez, penumbra, Aether.Extras, MonoGame.Extended and FlatRedBall): HLSL that fxport refused or
// crashed on, or compiled to GLSL whose result differs from fxc's. Each is a small source of our
// own in the project's shape, with what the construct means asserted on the GLSL or the error.
#include <gtest/gtest.h>

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "fxport/xlate/diagnostics.h"
#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

namespace {

fs::path writeSource(const std::string& name, const std::string& source) {
    fs::path dir = fs::temp_directory_path() / ("fxport-eighth-wave-" + std::to_string(::getpid()));
    fs::create_directories((dir / name).parent_path());
    std::ofstream(dir / name) << source;
    return dir / name;
}

CompiledEffect compileLoose(const std::string& source, const std::string& profile, const std::string& entry = "main") {
    CompileOptions o;
    o.useCache = false;
    return compileShaderFiles({{writeSource("shader.hlsl", source).string(), entry, profile}}, o);
}

std::string glslOf(const std::string& source, const std::string& profile) {
    try {
        return compileLoose(source, profile).shaders.at(0).glsl;
    } catch (const CompileError& err) {
        ADD_FAILURE() << err.what();
        return {};
    }
}

std::vector<Diagnostic> errorsOf(const std::string& source, const std::string& profile) {
    try {
        compileLoose(source, profile);
    } catch (const CompileError& err) {
        return err.diagnostics();
    }
    ADD_FAILURE() << "compiled";
    return {};
}

}  // namespace

// OpenXRay's particle.ps: `#define DEPTH_EPSILON 0.1h` and `spaceDepth < -2*DEPTH_EPSILON`. fxc
// computes half as float, so the product is the float 0.2; glslang refused an int beside the
// half literal ("Could not perform requested binary operation"). The folded constant is float32's
// 2 * 0.1.
TEST(RealworldEighthWave, HalfLiteralsAreFloats) {
    const std::string glsl = glslOf(
        "#define EPSILON 0.1h\n"
        "float4 main(float4 c : COLOR0) : SV_Target {\n"
        "    float d = c.x;\n"
        "    if (d < -2 * EPSILON) d = 100000.0h;\n"
        "    return d * (2 * 0.25H);\n"
        "}\n",
        "ps_5_0");
    EXPECT_NE(glsl.find("-0.20000000298023223876953125"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("100000.0"), std::string::npos) << glsl;
    EXPECT_NE(glsl.find("0.5"), std::string::npos) << glsl;
}
