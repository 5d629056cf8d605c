// fxport: the effect compiler's command line.
//   fxport compile IN.fx -o OUT [-I dir] [-D NAME=VALUE] [--technique NAME] [--no-cache]
//   fxport dump IN.fx [--reflection] [-I dir] [-D NAME=VALUE]
//   fxport check PATH... [-I dir] [-D NAME=VALUE] [--no-cache] [--warnings]
// Exit status: 0 success, 1 an effect failed to compile, 2 bad usage.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;

namespace {

const char* kUsage =
    "usage: fxport compile IN.fx -o OUT [-I dir] [-D NAME=VALUE] [--technique NAME] [--no-cache]\n"
    "       fxport dump IN.fx [--reflection] [-I dir] [-D NAME=VALUE]\n"
    "       fxport check PATH... [-I dir] [-D NAME=VALUE] [--no-cache] [--warnings]\n";

struct Args {
    std::string command;
    std::vector<std::string> inputs;
    std::string output;
    CompileOptions options;
    bool reflectionOnly = false;
    bool showWarnings = false;
};

bool parseArgs(int argc, char** argv, Args& a, std::string& error) {
    if (argc < 2) {
        error = "missing command";
        return false;
    }
    a.command = argv[1];
    for (int i = 2; i < argc; ++i) {
        std::string s = argv[i];
        auto value = [&](std::string& out) {
            if (s.size() > 2 && (s.rfind("-I", 0) == 0 || s.rfind("-D", 0) == 0 || s.rfind("-o", 0) == 0)) {
                out = s.substr(2);
                return true;
            }
            if (i + 1 >= argc) {
                error = "option " + s + " needs a value";
                return false;
            }
            out = argv[++i];
            return true;
        };
        std::string v;
        if (s.rfind("-I", 0) == 0) {
            if (!value(v)) return false;
            a.options.includeDirs.push_back(v);
        } else if (s.rfind("-D", 0) == 0) {
            if (!value(v)) return false;
            auto eq = v.find('=');
            a.options.defines.push_back({v.substr(0, eq), eq == std::string::npos ? "1" : v.substr(eq + 1)});
        } else if (s.rfind("-o", 0) == 0) {
            if (!value(a.output)) return false;
        } else if (s == "--technique") {
            if (!value(v)) return false;
            a.options.techniques.push_back(v);
        } else if (s == "--no-cache") {
            a.options.useCache = false;
        } else if (s == "--reflection") {
            a.reflectionOnly = true;
        } else if (s == "--warnings") {
            a.showWarnings = true;
        } else if (!s.empty() && s[0] == '-') {
            error = "unknown option " + s;
            return false;
        } else {
            a.inputs.push_back(s);
        }
    }
    return true;
}

void printDiagnostics(const std::vector<Diagnostic>& diags, bool warnings) {
    for (const auto& d : diags)
        if (d.severity == Severity::Error || warnings) std::cerr << d.format() << "\n";
}

std::string typeText(const Parameter& p) {
    static const char* scalar[] = {"void", "bool", "int", "uint", "float"};
    if (p.parameterClass == ParameterClass::Object || p.parameterClass == ParameterClass::Struct) {
        static const char* objects[] = {"void", "bool", "int", "uint", "float", "string", "texture", "texture1D", "texture2D",
                                        "texture3D", "textureCUBE", "sampler", "sampler1D", "sampler2D", "sampler3D", "samplerCUBE",
                                        "SamplerState"};
        return p.parameterClass == ParameterClass::Struct ? "struct" : objects[static_cast<int>(p.type)];
    }
    std::string t = scalar[std::min(4, static_cast<int>(p.type))];
    if (p.parameterClass == ParameterClass::Matrix) t += std::to_string(p.rows) + "x" + std::to_string(p.columns);
    else if (p.parameterClass == ParameterClass::Vector) t += std::to_string(p.columns);
    return t;
}

void dump(const CompiledEffect& e, std::ostream& out) {
    out << "effect " << e.sourcePath << "\n\nuniform blocks:\n";
    for (const auto& b : e.uniformBlocks)
        out << "  " << b.name << ": binding " << b.binding << ", " << b.size << " bytes" << (b.size ? "" : " (read by no shader)") << "\n";
    out << "\nparameters (" << e.parameters.size() << "):\n";
    for (const auto& p : e.parameters) {
        out << "  " << typeText(p) << " " << p.name;
        if (p.elements) out << "[" << p.elements << "]";
        if (!p.semantic.empty()) out << " : " << p.semantic;
        if (!p.defaultValue.empty()) {
            out << " = {";
            for (size_t i = 0; i < p.defaultValue.size(); ++i) out << (i ? ", " : "") << p.defaultValue[i];
            out << "}";
        }
        if (!p.defaultString.empty()) out << " = \"" << p.defaultString << "\"";
        if (p.offset >= 0) out << "   @" << (p.block ? e.uniformBlocks[static_cast<size_t>(p.block)].name + "+" : std::string()) << p.offset << " size " << p.size << (p.parameterClass == ParameterClass::Matrix ? (p.rowMajor ? " row_major" : " column_major") : "");
        for (const auto& a : p.annotations) out << "  <" << a.type << " " << a.name << " = " << a.value << ">";
        out << "\n";
    }
    auto choice = [&](const ShaderChoice& c) {
        std::string s;
        for (size_t i = 0; i < c.shaders.size(); ++i) s += (i ? "|" : "") + (c.shaders[i] < 0 ? std::string("null") : "#" + std::to_string(c.shaders[i]));
        if (!c.selector.empty()) s += " (chosen at Apply by index)";
        return s.empty() ? std::string("none") : s;
    };
    out << "\ntechniques:\n";
    for (const auto& t : e.techniques) {
        out << "  technique " << t.name << "\n";
        for (const auto& p : t.passes) {
            out << "    pass " << p.name << (p.valid ? "" : "  [INVALID]") << ": vs " << choice(p.vertexShader) << ", ps " << choice(p.pixelShader);
            if (!p.geometryShader.shaders.empty()) out << ", gs " << choice(p.geometryShader);
            out << "\n";
            for (const auto& s : p.states) out << "      " << describeStateAssignment(s, e) << "\n";
        }
    }
    out << "\nshaders:\n";
    for (size_t i = 0; i < e.shaders.size(); ++i) {
        const auto& s = e.shaders[i];
        out << "  #" << i << " " << s.profile.name << " " << s.entryPoint << "(" << s.arguments << ")" << (s.needsD3D9PixelOffset ? "  [D3D9 half-pixel offset]" : "") << "\n";
        for (const auto& in : s.inputs) out << "    input " << in.semantic << " -> location " << in.location << "\n";
        for (const auto& b : s.samplers)
            out << "    sampler unit " << b.unit << ": " << b.glslName << (b.textureParameter.empty() ? "" : " <- texture " + b.textureParameter) << "\n";
        out << "    reads:";
        for (int p : s.parametersRead) out << " " << e.parameters[static_cast<size_t>(p)].name;
        out << "\n    --- GLSL ---\n" << s.glsl << "\n";
    }
}

std::vector<std::string> collectEffects(const std::vector<std::string>& paths, std::vector<std::string>& missing) {
    std::vector<std::string> files;
    for (const auto& p : paths) {
        std::error_code ec;
        if (fs::is_directory(p, ec)) {
            std::vector<std::string> found;
            for (const auto& entry : fs::recursive_directory_iterator(p, ec))
                if (entry.is_regular_file() && (entry.path().extension() == ".fx" || entry.path().extension() == ".FX"))
                    found.push_back(entry.path().string());
            std::sort(found.begin(), found.end());
            files.insert(files.end(), found.begin(), found.end());
        } else if (fs::exists(p, ec)) {
            files.push_back(p);
        } else {
            missing.push_back(p);
        }
    }
    return files;
}

}  // namespace

int main(int argc, char** argv) {
    Args a;
    std::string error;
    if (!parseArgs(argc, argv, a, error)) {
        std::cerr << "fxport: " << error << "\n" << kUsage;
        return 2;
    }
    try {
        if (a.command == "compile") {
            if (a.inputs.size() != 1 || a.output.empty()) {
                std::cerr << "fxport: compile needs one input and -o OUT\n" << kUsage;
                return 2;
            }
            CompiledEffect e = compileEffectFile(a.inputs[0], a.options);
            printDiagnostics(e.diagnostics, true);
            saveEffectFile(e, a.output);
            return 0;
        }
        if (a.command == "dump") {
            if (a.inputs.size() != 1) {
                std::cerr << "fxport: dump needs one input\n" << kUsage;
                return 2;
            }
            CompiledEffect e = compileEffectFile(a.inputs[0], a.options);
            printDiagnostics(e.diagnostics, true);
            if (a.reflectionOnly) std::cout << reflectionJson(e);
            else dump(e, std::cout);
            return 0;
        }
        if (a.command == "check") {
            if (a.inputs.empty()) {
                std::cerr << "fxport: check needs at least one path\n" << kUsage;
                return 2;
            }
            std::vector<std::string> missing;
            auto files = collectEffects(a.inputs, missing);
            int passed = 0, failed = 0;
            for (const auto& m : missing) {
                std::cout << m << ": error FX1001: no such file or folder\n";
                ++failed;
            }
            for (const auto& f : files) {
                try {
                    CompiledEffect e = compileEffectFile(f, a.options);
                    std::cout << f << ": ok (" << e.techniques.size() << " techniques, " << e.shaders.size() << " shaders)\n";
                    // States the effect sets that fxport ignores are listed always; other warnings on --warnings.
                    for (const auto& d : e.diagnostics)
                        if (d.severity == Severity::Warning && (a.showWarnings || d.dropsState())) std::cerr << d.format() << "\n";
                    ++passed;
                } catch (const CompileError& ce) {
                    const auto& d = ce.diagnostics().front();
                    std::cout << d.format() << "\n";
                    ++failed;
                }
            }
            std::cout << passed << " passed, " << failed << " failed\n";
            return failed ? 1 : 0;
        }
        std::cerr << "fxport: unknown command '" << a.command << "'\n" << kUsage;
        return 2;
    } catch (const CompileError& e) {
        printDiagnostics(e.diagnostics(), true);
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "fxport: internal error: " << e.what() << "\n";
        return 1;
    }
}
