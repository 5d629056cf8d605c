// libFuzzer harness over loose shader files (compileShaderFiles: fxc /E /T, D3DCompileFromFile,
// Effect::FromShaderFiles, `fxport compile X.hlsl --entry --profile`): entry points of one file
// compile together, files compile apart sharing varying locations and are merged into one effect.
// The input is fuzz_input.h's format; the main file is main.hlsl, and every file whose first line
// is `//entries: NAME PROFILE [NAME PROFILE ...]` is compiled with those entry points (at most 4 in
// all; none at all: main.hlsl's `main` as ps_4_0). The front end runs in process, as in
// fuzz_compile, so a crash inside glslang is a finding (the product contains it: FX9001).
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <sstream>

#include "fuzz_input.h"
#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"

using namespace fxport;

namespace {

// The entry points a file's first line names.
void addEntries(const fuzz::FuzzFile& file, const std::string& path, std::vector<xlate::ShaderEntry>& entries) {
    static constexpr std::string_view kTag = "//entries:";
    if (file.text.compare(0, kTag.size(), kTag) != 0) return;
    std::istringstream line(file.text.substr(kTag.size(), file.text.find('\n') - kTag.size()));
    std::string name, profile;
    while (entries.size() < 4 && line >> name >> profile) entries.push_back({path, name, profile});
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1) return 0;
    uint8_t mode = data[0];
    auto files = fuzz::splitInput(std::string_view(reinterpret_cast<const char*>(data) + 1, size - 1));
    files[0].name = "main.hlsl";
    for (size_t i = 1; i < files.size(); ++i)
        if (files[i].name == "main.hlsl") files[i].name = "main2.hlsl";
    auto dir = fuzz::writeFiles(files);
    std::vector<xlate::ShaderEntry> entries;
    for (const auto& f : files) addEntries(f, (dir / f.name).string(), entries);
    if (entries.empty()) entries.push_back({(dir / "main.hlsl").string(), "main", "ps_4_0"});
    xlate::CompileOptions options;
    options.useCache = false;
    options.inProcess = true;
    options.keepRewrittenHlsl = (mode & 1) != 0;
    if (mode & 2) options.defines.push_back({"FUZZ_DEFINE", "1"});
    xlate::CompiledEffect effect;
    try {
        effect = xlate::compileShaderFiles(entries, options);
    } catch (const xlate::CompileError& e) {
        if (e.diagnostics().empty()) {
            std::cerr << "CompileError without diagnostics\n";
            std::abort();
        }
        return 0;
    } catch (const std::exception& e) {
        std::cerr << "escaped exception (not a CompileError): " << e.what() << "\n";
        std::abort();
    }
    // The merged effect must be a valid compiled-effect file that loads back the same.
    try {
        std::string file = xlate::serializeEffect(effect);
        xlate::CompiledEffect back = xlate::deserializeEffect(file, "fuzz");
        if (xlate::serializeEffect(back) != file) {
            std::cerr << "compiled-effect file does not round-trip\n";
            std::abort();
        }
    } catch (const std::exception& e) {
        std::cerr << "a compiled effect does not load back: " << e.what() << "\n";
        std::abort();
    }
    return 0;
}
