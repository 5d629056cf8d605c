// fxport: the effect compiler's command line.
//   fxport compile IN.fx -o OUT [-I dir] [-D NAME=VALUE] [--technique NAME] [--no-cache] [--depfile FILE]
//   fxport dump IN.fx [--reflection] [-I dir] [-D NAME=VALUE]
//   fxport check PATH... [-I dir] [-D NAME=VALUE] [--no-cache] [--warnings]
//   --entry NAME --profile P (repeatable): a loose shader file (no technique) by entry point, as fxc /E /T
//   --root DIR: every #include must stay inside DIR (or an -I folder); default: includes resolve
//   anywhere, as with fxc
//   fxport --help | fxport COMMAND --help | fxport --version
// fxc spellings are accepted beside the long forms: /E, /T, /D, /I, /Fo, /?; /Zpr and /Zpc set
// the default matrix majority, fxc's optimisation/strip switches are ignored (fxc_switches.h).
// Exit status: 0 success, 1 an effect failed to compile, 2 bad usage (one line naming the option).
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"
#include "fxc_switches.h"
#include "output_file.h"

namespace fs = std::filesystem;
using namespace fxport::xlate;
namespace cli = fxport::cli;

namespace {

const char* kUsage =
    "usage: fxport compile IN.fx -o OUT [-I dir] [-D NAME=VALUE] [--technique NAME] [--no-cache] [--depfile FILE]\n"
    "       fxport compile IN.hlsl -o OUT --entry NAME --profile vs_5_0 [--entry NAME --profile ps_5_0]\n"
    "       fxport dump IN.fx [--reflection] [-I dir] [-D NAME=VALUE]\n"
    "       fxport check PATH... [-I dir] [-D NAME=VALUE] [--no-cache] [--warnings]\n"
    "       (all: --root DIR confines every #include to DIR and the -I folders)\n"
    "       fxport --version | fxport --help | fxport COMMAND --help\n";

const char* kHelp =
    "fxport: compiles Direct3D 9-11 effects (.fx, as written for XNA 4 and D3D10/11) to GLSL 4.50 with\n"
    "reflection and pass states, for the fxport runtime (Effect::FromCompiledFile loads the output).\n"
    "\n"
    "commands:\n"
    "  compile   compile one effect to a compiled-effect file (what fxport_add_effects runs)\n"
    "  dump      print an effect's techniques, states, parameters and GLSL (or its reflection as JSON)\n"
    "  check     compile every .fx under the given files/folders, one line each\n"
    "\n"
    "options of every command:\n"
    "  -I DIR, /I DIR           a folder #include may read from (repeatable)\n"
    "  -D NAME[=VALUE], /D ...  define a macro before the source (repeatable; VALUE defaults to 1)\n"
    "  --root DIR               every #include must stay inside DIR or an -I folder (FX1103 otherwise);\n"
    "                           default: #include \"../x.fxh\" resolves wherever it leads, as with fxc\n"
    "  --entry NAME --profile P, /E NAME /T P\n"
    "                           a loose shader file (no technique): compile entry point NAME for\n"
    "                           profile P (vs_5_0, ps_4_0 ...); repeatable, one --profile per --entry\n"
    "  --profile fx_N_N, /T fx_5_0\n"
    "                           the effect profile fxc's /T names (fx_2_0, fx_4_0, fx_4_1, fx_5_0): from\n"
    "                           fx_4_0 on an effect without technique (variables, functions) compiles\n"
    "  /Zpr, /Zpc (-Zpr, -Zpc)  fxc's default matrix packing: matrices that name no majority are\n"
    "                           row_major (/Zpr) or column_major (/Zpc, the default) until a\n"
    "                           #pragma pack_matrix\n"
    "  /O0../O3 /Od /Zi /nologo /Qstrip_reflect /Qstrip_debug /Ges /Gis\n"
    "                           fxc switches that change nothing fxport emits: accepted, ignored;\n"
    "                           /Gec /Gfa /Gfp /Gpp change what fxc computes and are refused\n"
    "  -h, --help, /?           help (after a command: that command's help)\n"
    "  --version                print fxport's version\n"
    "\n"
    "Diagnostics read file(line,col): error FXnnnn: message. Exit status: 0 ok, 1 an effect failed,\n"
    "2 bad usage. Environment: FXPORT_CACHE_DIR (compile cache), FXPORT_DUMP=DIR (rewritten HLSL, GLSL).\n"
    "'fxport COMMAND --help' lists a command's options.\n";

const char* commandHelp(const std::string& command) {
    if (command == "compile")
        return "usage: fxport compile IN.fx -o OUT [options]\n"
               "Compiles IN.fx (every technique) and writes the compiled effect (JSON) to OUT.\n"
               "  -o OUT, /Fo OUT       the compiled-effect file to write (required)\n"
               "  -I DIR, /I DIR        a folder #include may read from (repeatable)\n"
               "  -D NAME[=VALUE], /D   define a macro (repeatable)\n"
               "  --technique NAME      compile only this technique (repeatable)\n"
               "  --no-cache            do not read or write the compile cache\n"
               "  --depfile FILE        also write FILE: Make-style dependencies of OUT (the effect and\n"
               "                        every file it #includes), for Ninja/Make depfile support\n"
               "  /E NAME, /T PROFILE   fxc's entry point and profile (for loose shaders); /T fx_5_0 alone is\n"
               "                        the effect's profile\n"
               "  /Zpr, /Zpc            row-major / column-major matrices by default (fxc's packing)\n"
               "  /O3, /nologo ...      fxc's optimisation, debug and strip switches: ignored (see\n"
               "                        'fxport --help'); other unknown /X switches are errors\n";
    if (command == "dump")
        return "usage: fxport dump IN.fx [options]\n"
               "Prints the effect's uniform blocks, parameters, techniques with their states, and each\n"
               "shader's inputs, samplers and GLSL.\n"
               "  --reflection          print the reflection as JSON instead (no GLSL)\n"
               "  -I DIR, /I DIR        a folder #include may read from (repeatable)\n"
               "  -D NAME[=VALUE], /D   define a macro (repeatable)\n";
    if (command == "check")
        return "usage: fxport check PATH... [options]\n"
               "Compiles each effect file, and every .fx under each folder; prints one line per effect,\n"
               "then \"N passed, M failed\". Exit status 1 when any failed.\n"
               "  -I DIR, /I DIR        a folder #include may read from (repeatable)\n"
               "  -D NAME[=VALUE], /D   define a macro (repeatable)\n"
               "  --no-cache            do not read or write the compile cache\n"
               "  --warnings            print warnings too\n";
    return nullptr;
}

struct Args {
    std::string command;
    std::vector<std::string> inputs;
    std::string output;
    std::string depfile;
    CompileOptions options;
    bool reflectionOnly = false;
    bool showWarnings = false;
    bool help = false;
    bool version = false;
    std::vector<std::string> given;  // options as typed, to say which do not belong to the command
    std::vector<ShaderEntry> entries;  // --entry NAME --profile P (fxc /E /T), for loose shader files
    int profiles = 0;
    std::string majoritySwitch;  // /Zpr or /Zpc as typed, once given
};

// A loose shader file with --entry/--profile (fxc /E /T), else an effect.
CompiledEffect compileInput(const std::string& file, const Args& a, const CompileOptions& options) {
    if (a.entries.empty()) return compileEffectFile(file, options);
    std::vector<ShaderEntry> entries = a.entries;
    for (auto& e : entries) e.path = file;
    return compileShaderFiles(entries, options);
}

// A -D's name is a macro name, optionally with a parameter list; neither part may hold a line
// break (it would start a directive of its own in the preamble).
bool validDefine(const std::string& name, const std::string& body) {
    if (name.empty() || !(std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_')) return false;
    size_t i = 0;
    while (i < name.size() && (std::isalnum(static_cast<unsigned char>(name[i])) || name[i] == '_')) ++i;
    bool paramsOk = i == name.size() || (name[i] == '(' && name.back() == ')' && name.find_first_of("()", i + 1) == name.size() - 1);
    return paramsOk && name.find_first_of("\r\n") == std::string::npos && body.find_first_of("\r\n") == std::string::npos;
}

// fxc's switches (fxc /?) beside ours. An argument with an attached value (/Tps_3_0, /DNAME=1,
// /Foout.fxo) is a switch only when it is not a path: its first component (/tmp, /home) is not a
// folder at the root, so absolute paths keep working.
struct FxcAlias {
    const char* fxc;
    const char* ours;
};
const FxcAlias kFxcAliases[] = {{"/Fo", "-o"}, {"/E", "--entry"}, {"/T", "--profile"}, {"/D", "-D"}, {"/I", "-I"}, {"/?", "--help"}};

// Rewrites fxc switches to our spellings, remembering what was typed (for messages).
std::vector<std::pair<std::string, std::string>> withFxcAliases(int argc, char** argv) {
    std::vector<std::pair<std::string, std::string>> out;  // (ours, as typed)
    for (int i = 1; i < argc; ++i) {
        std::string s = argv[i];
        bool done = false;
        if (!s.empty() && s[0] == '/') {
            for (const auto& a : kFxcAliases) {
                size_t n = std::strlen(a.fxc);
                if (s == a.fxc) {
                    out.push_back({a.ours, s});
                    done = true;
                } else if (s.compare(0, n, a.fxc) == 0 && cli::isSlashSwitch(s)) {
                    out.push_back({a.ours, a.fxc});
                    out.push_back({s.substr(n), s.substr(n)});
                    done = true;
                }
                if (done) break;
            }
        }
        if (!done) out.push_back({s, s});
    }
    return out;
}

// fxc's value-less switches (fxc_switches.h), spelled /X or -X: 0 when `s` is none, 1 when it is
// taken (or ignored), -1 when it is refused (`error` says why).
int takeFxcSwitch(const std::string& s, Args& a, std::string& error) {
    if (s.size() < 2 || (s[0] != '/' && s[0] != '-')) return 0;
    const cli::FxcSwitch given = cli::fxcSwitch(s.substr(1));
    switch (given.action) {
        case cli::FxcSwitchAction::NotASwitch:
            return 0;
        case cli::FxcSwitchAction::Ignore:
            return 1;
        case cli::FxcSwitchAction::Refuse:
            error = "option '" + s + "' " + given.why;
            return -1;
        case cli::FxcSwitchAction::RowMajor:
        case cli::FxcSwitchAction::ColumnMajor:
            break;
    }
    const std::string majority = given.action == cli::FxcSwitchAction::RowMajor ? "row_major" : "column_major";
    if (!a.majoritySwitch.empty() && a.options.defaultMatrixMajority != majority) {
        error = "options '" + a.majoritySwitch + "' and '" + s + "' exclude each other (matrices are row-major or column-major)";
        return -1;
    }
    a.options.defaultMatrixMajority = majority;
    a.majoritySwitch = s;
    return 1;
}

bool parseArgs(int argc, char** argv, Args& a, std::string& error) {
    auto args = withFxcAliases(argc, argv);
    size_t first = 0;
    if (!args.empty() && (args[0].first == "--help" || args[0].first == "-h" || args[0].first == "--version")) {
        a.help = args[0].first != "--version";
        a.version = !a.help;
        if (args.size() > 1) {
            error = "option '" + args[0].second + "' takes no further arguments (got '" + args[1].second + "')";
            return false;
        }
        return true;
    }
    if (args.empty()) {
        error = "missing command (compile, dump or check; see 'fxport --help')";
        return false;
    }
    a.command = args[first].first;
    for (size_t i = first + 1; i < args.size(); ++i) {
        std::string s = args[i].first;
        const std::string& typed = args[i].second;
        auto value = [&](std::string& out) {
            if (s.size() > 2 && (s.rfind("-I", 0) == 0 || s.rfind("-D", 0) == 0 || s.rfind("-o", 0) == 0)) {
                out = s.substr(2);
                return true;
            }
            if (i + 1 >= args.size()) {
                error = "option '" + typed + "' needs a value";
                return false;
            }
            out = args[++i].first;
            if (out.empty()) {
                error = "option '" + typed + "' has an empty value";
                return false;
            }
            return true;
        };
        std::string v;
        if (s == "--help" || s == "-h") {
            a.help = true;
            continue;
        }
        if (const int taken = takeFxcSwitch(s, a, error)) {
            if (taken < 0) return false;
            continue;
        }
        if (!s.empty() && s[0] == '-') a.given.push_back(typed.rfind("-", 0) == 0 && typed.size() > 2 && typed[1] != '-' ? typed.substr(0, 2) : typed);
        if (s.rfind("-I", 0) == 0) {
            if (!value(v)) return false;
            std::error_code ec;
            if (!fs::is_directory(v, ec)) {
                error = "option '-I' has a bad value '" + v + "': not a folder";
                return false;
            }
            a.options.includeDirs.push_back(v);
        } else if (s.rfind("-D", 0) == 0) {
            if (!value(v)) return false;
            auto eq = v.find('=');
            std::string name = v.substr(0, eq), body = eq == std::string::npos ? "1" : v.substr(eq + 1);
            if (!validDefine(name, body)) {
                error = "option '" + typed.substr(0, 2) + "' has a bad value '" + v + "': want NAME, NAME=VALUE or NAME(ARGS)=VALUE";
                return false;
            }
            a.options.defines.push_back({name, body});
        } else if (s.rfind("-o", 0) == 0) {
            if (!value(a.output)) return false;
        } else if (s == "--entry") {
            if (!value(v)) return false;
            a.entries.push_back({{}, v, {}});
        } else if (s == "--profile") {
            if (!value(v)) return false;
            if (v.rfind("fx_", 0) == 0) {  // fxc /T fx_5_0 effect.fx: the effect's profile (Luna's DX11 projects)
                a.options.effectProfile = v;
                continue;
            }
            if (a.entries.empty() || a.profiles >= static_cast<int>(a.entries.size())) {
                error = "option '" + typed + "' (" + v + ") needs an --entry before it (--entry NAME --profile vs_5_0)";
                return false;
            }
            a.entries[static_cast<size_t>(a.profiles++)].profile = v;
        } else if (s == "--root") {
            if (!value(a.options.includeRoot)) return false;
        } else if (s == "--depfile") {
            if (!value(a.depfile)) return false;
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
            error = "option '" + typed + "' is unknown (see 'fxport " + a.command + " --help')";
            return false;
        } else if (cli::isSlashSwitch(s)) {
            error = "option '" + typed + "' is unknown: not an fxc switch fxport reads, nor an existing path (see 'fxport " + a.command + " --help')";
            return false;
        } else {
            a.inputs.push_back(s);
        }
    }
    if (a.profiles != static_cast<int>(a.entries.size())) {
        error = "option '--entry' (" + a.entries.back().entryPoint + ") needs a --profile after it (--entry NAME --profile ps_5_0)";
        return false;
    }
    return true;
}

// Options that only one command reads; given to another they would be ignored silently.
std::string misplacedOption(const Args& a) {
    struct Only {
        const char* option;
        const char* command;
    };
    static const Only only[] = {{"-o", "compile"}, {"/Fo", "compile"}, {"--depfile", "compile"}, {"--reflection", "dump"}, {"--warnings", "check"}};
    for (const auto& given : a.given)
        for (const auto& o : only)
            if (given == o.option && a.command != o.command)
                return "option '" + given + "' is not an option of '" + a.command + "' (only of '" + o.command + "')";
    return {};
}

// Make's syntax: spaces, '#' and '$' escaped; Ninja reads the same.
std::string makeEscaped(const std::string& path) {
    std::string out;
    for (char c : path) {
        if (c == ' ' || c == '#' || c == '\\') out += '\\';
        if (c == '$') out += '$';
        out += c;
    }
    return out;
}

std::string depfileText(const std::string& output, const std::vector<std::string>& files) {
    std::string text = makeEscaped(output) + ":";
    for (const auto& f : files) text += " \\\n  " + makeEscaped(f);
    return text + "\n";
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
            if (!p.hullShader.shaders.empty()) out << ", hs " << choice(p.hullShader);
            if (!p.domainShader.shaders.empty()) out << ", ds " << choice(p.domainShader);
            if (!p.computeShader.shaders.empty()) out << ", cs " << choice(p.computeShader);
            out << "\n";
            for (const auto& s : p.states) out << "      " << describeStateAssignment(s, e) << "\n";
            for (const auto& ts : p.textureStages)  // set on the device for later passes (D3D9)
                out << "      texture stage " << ts.stage << (ts.textureParameter.empty() ? "" : " <- texture " + ts.textureParameter)
                    << " (no shader of this pass samples it: kept for later passes)\n";
        }
    }
    out << "\nshaders:\n";
    for (size_t i = 0; i < e.shaders.size(); ++i) {
        const auto& s = e.shaders[i];
        out << "  #" << i << " " << s.profile.name << " " << s.entryPoint << "(" << s.arguments << ")" << (s.needsD3D9PixelOffset ? "  [D3D9 half-pixel offset]" : "") << "\n";
        if (s.profile.stage == ShaderStage::Compute)
            out << "      numthreads(" << s.threadGroupSize[0] << ", " << s.threadGroupSize[1] << ", " << s.threadGroupSize[2] << ")\n";
        if (!s.tessellation.domain.empty())
            out << "      tessellation: domain " << s.tessellation.domain << (s.tessellation.partitioning.empty() ? "" : ", partitioning " + s.tessellation.partitioning)
                << (s.tessellation.outputTopology.empty() ? "" : ", topology " + s.tessellation.outputTopology)
                << (s.tessellation.patchConstantFunction.empty() ? "" : ", patch constants " + s.tessellation.patchConstantFunction)
                << ", control points " << s.tessellation.inputControlPoints << " -> " << s.tessellation.outputControlPoints << "\n";
        static const char* const kKinds[] = {"buffer ", "image ", "texel buffer ", "image buffer "};
        static const char* const kUnits[] = {"SSBO binding ", "image unit ", "texture unit ", "image unit "};
        for (const auto& b : s.storage)
            out << "      " << kKinds[int(b.kind)] << b.name << " : register(" << b.registerClass << b.slot << ") -> "
                << kUnits[int(b.kind)] << b.binding << (b.writes ? " (read/write)" : " (read)")
                << (b.format.empty() ? "" : ", " + b.format) << (b.stride ? ", stride " + std::to_string(b.stride) : "") << "\n";
        for (const auto& in : s.inputs) out << "    input " << in.semantic << " -> location " << in.location << "\n";
        for (const auto& b : s.samplers)
            out << "    sampler unit " << b.unit << ": " << b.glslName << (b.textureParameter.empty() ? "" : " <- texture " + b.textureParameter) << "\n";
        out << "    reads:";
        for (int p : s.parametersRead) out << " " << e.parameters[static_cast<size_t>(p)].name;
        out << "\n    --- GLSL ---\n" << s.glsl << "\n";
    }
}

// Directory scans take effects in any case (.fx, .Fx, .FX); headers (.fxh, .hlsli ...) and loose
// shader files (.hlsl, .vs, .ps: they need --entry and --profile) are compiled only when named.
bool isEffectFile(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".fx";
}

bool isHeaderFile(const fs::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".fxh" || ext == ".hlsli";
}

// The effect files named, and those found by scanning the folders named, in order.
std::vector<std::string> collectEffects(const std::vector<std::string>& paths, std::vector<std::string>& missing) {
    std::vector<std::string> files;
    for (const auto& p : paths) {
        std::error_code ec;
        if (fs::is_directory(p, ec)) {
            std::vector<std::string> found;
            for (const auto& entry : fs::recursive_directory_iterator(p, ec))
                if (entry.is_regular_file() && isEffectFile(entry.path()))
                    found.push_back(entry.path().string());
            std::sort(found.begin(), found.end());
            for (auto& f : found) files.push_back(std::move(f));
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
        std::cerr << "fxport: " << error << "\n";
        return 2;
    }
    if (a.version) {
        std::cout << "fxport " << FXPORT_VERSION << " (effect compiler " << compilerVersion() << ")\n";
        return 0;
    }
    if (a.help && a.command.empty()) {
        std::cout << kHelp << "\n" << kUsage;
        return 0;
    }
    const char* help = commandHelp(a.command);
    if (!help) {
        std::cerr << "fxport: unknown command '" << a.command << "' (commands: compile, dump, check; see 'fxport --help')\n";
        return 2;
    }
    if (a.help) {
        std::cout << help;
        return 0;
    }
    if (std::string misplaced = misplacedOption(a); !misplaced.empty()) {
        std::cerr << "fxport: " << misplaced << "\n";
        return 2;
    }
    try {
        if (a.command == "compile") {
            if (a.inputs.size() != 1 || a.output.empty()) {
                std::cerr << "fxport: compile needs one input and -o OUT (see 'fxport compile --help')\n";
                return 2;
            }
            std::vector<cli::NamedFile> outputs = {{"-o", a.output}};
            if (!a.depfile.empty()) outputs.push_back({"--depfile", a.depfile});
            std::vector<cli::NamedFile> inputs = {{"the input", a.inputs[0]}};
            if (std::string same = cli::findSameFile(outputs, inputs); !same.empty()) {
                std::cerr << "fxport: " << same << "; name another file\n";
                return 2;
            }
            CompiledEffect e = compileInput(a.inputs[0], a, a.options);
            printDiagnostics(e.diagnostics, true);
            // The included files are known once the compile has read them (and checked its limits).
            std::vector<std::string> dependencies = effectDependencies(a.inputs[0], a.options);
            for (const auto& d : dependencies) inputs.push_back({"the included file", d});
            if (std::string same = cli::findSameFile(outputs, inputs); !same.empty()) {
                std::cerr << "fxport: " << same << "; name another file\n";
                return 2;
            }
            std::string writeError;
            // The depfile first: an output without its depfile would be taken as up to date.
            if (!a.depfile.empty() && !cli::writeOutputFile(a.depfile, depfileText(a.output, dependencies), writeError)) {
                std::cerr << "fxport: --depfile: " << writeError << "\n";
                return 1;
            }
            if (!cli::writeOutputFile(a.output, serializeEffect(e), writeError)) {
                std::cerr << "fxport: -o: " << writeError << "\n";
                return 1;
            }
            return 0;
        }
        if (a.command == "dump") {
            if (a.inputs.size() != 1) {
                std::cerr << "fxport: dump needs one input (see 'fxport dump --help')\n";
                return 2;
            }
            CompiledEffect e = compileInput(a.inputs[0], a, a.options);
            printDiagnostics(e.diagnostics, true);
            if (a.reflectionOnly) std::cout << reflectionJson(e);
            else dump(e, std::cout);
            return 0;
        }
        if (a.command == "check") {
            if (a.inputs.empty()) {
                std::cerr << "fxport: check needs at least one path (see 'fxport check --help')\n";
                return 2;
            }
            std::vector<std::string> missing;
            auto files = collectEffects(a.inputs, missing);
            int passed = 0, failed = 0;
            for (const auto& m : missing) {
                std::cout << m << ": error FX1001: no such file or folder\n";
                ++failed;
            }
            // One line per file, in order; the effects compile in parallel (compileEffectFiles).
            auto report = [&](const std::string& f, EffectFileResult&& r) {
                if (!r.effect) {
                    std::cout << r.errors.front().format() << "\n";
                    ++failed;
                    return;
                }
                const CompiledEffect& e = *r.effect;
                std::cout << f << ": ok (" << e.techniques.size() << " techniques, " << e.shaders.size() << " shaders)" << std::endl;
                // States the effect sets that fxport ignores are listed always; other warnings on --warnings.
                for (const auto& d : e.diagnostics)
                    if (d.severity == Severity::Warning && (a.showWarnings || d.dropsState())) std::cerr << d.format() << "\n";
                ++passed;
            };
            std::vector<std::pair<std::string, CompileOptions>> jobs;
            for (const auto& f : files) jobs.push_back({f, a.options});
            // Headers are skipped where they stand in the list; loose shaders (--entry) compile one by one.
            std::vector<std::pair<std::string, CompileOptions>> effects;
            std::vector<size_t> after;  // effects[k] is reported after the skipped files before jobs index after[k]
            size_t shown = 0;
            auto showSkippedUpTo = [&](size_t end) {
                for (; shown < end; ++shown)
                    if (isHeaderFile(jobs[shown].first))
                        std::cout << jobs[shown].first << ": skipped: a header is compiled through the effects that #include it\n";
            };
            for (size_t i = 0; i < jobs.size(); ++i)
                if (!isHeaderFile(jobs[i].first)) effects.push_back(jobs[i]), after.push_back(i);
            if (a.entries.empty()) {
                compileEffectFiles(effects, [&](size_t k, EffectFileResult&& r) {
                    showSkippedUpTo(after[k]);
                    shown = after[k] + 1;
                    report(effects[k].first, std::move(r));
                });
            } else {
                for (size_t k = 0; k < effects.size(); ++k) {
                    showSkippedUpTo(after[k]);
                    shown = after[k] + 1;
                    EffectFileResult r;
                    try {
                        r.effect = compileInput(effects[k].first, a, effects[k].second);
                    } catch (const CompileError& ce) {
                        r.errors = ce.diagnostics();
                    }
                    report(effects[k].first, std::move(r));
                }
            }
            showSkippedUpTo(jobs.size());
            std::cout << passed << " passed, " << failed << " failed\n";
            return failed ? 1 : 0;
        }
        return 2;  // unreachable: commandHelp() knows every command
    } catch (const CompileError& e) {
        printDiagnostics(e.diagnostics(), true);
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "fxport: internal error: " << e.what() << "\n";
        return 1;
    }
}
