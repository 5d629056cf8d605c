// The alpha-test variant of a pixel shader's GLSL (see alpha_test.h).
#include "fxport/xlate/alpha_test.h"

#include <regex>

namespace fxport::xlate {

std::optional<std::string> alphaTestVariant(const std::string& glsl) {
    // SPIRV-Cross declares the outputs with explicit locations and writes them from main().
    static const std::regex output(R"(layout\(location = 0\) out vec4 (\w+);)");
    static const std::regex entry(R"(\bvoid main\(\))");
    std::smatch m;
    if (!std::regex_search(glsl, m, output)) return std::nullopt;
    const std::string target = m[1].str();
    if (!std::regex_search(glsl, entry)) return std::nullopt;
    std::string out = std::regex_replace(glsl, entry, "void fxport_shaderMain()", std::regex_constants::format_first_only);
    out += "\nuniform int " + std::string(kAlphaFuncUniform) + ";\nuniform float " + std::string(kAlphaRefUniform) +
           ";\n\nvoid main()\n{\n    fxport_shaderMain();\n    float a = " + target + ".a;\n    float r = " + kAlphaRefUniform +
           ";\n    int f = " + kAlphaFuncUniform +
           ";\n    bool keep = f == 8 || (f == 2 && a < r) || (f == 3 && a == r) || (f == 4 && a <= r) ||\n"
           "                (f == 5 && a > r) || (f == 6 && a != r) || (f == 7 && a >= r);\n"
           "    if (!keep) discard;\n}\n";
    return out;
}

}  // namespace fxport::xlate
