// libFuzzer harness over the whole effect compiler: preprocess (includes from the input, cycles
// possible) -> parse -> rewrite -> glslang -> SPIRV-Cross -> reflection -> compiled-effect file
// round trip. Runs the front end in this process (CompileOptions::inProcess), so a crash inside
// glslang is a finding, not a contained FX9001. A CompileError is the expected outcome for most
// inputs; any other exception is a bug (the compiler must turn every problem into a diagnostic).
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <iostream>

#include "fuzz_input.h"
#include "fxport/xlate/effect_compiler.h"
#include "fxport/xlate/effect_file.h"

using namespace fxport;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1) return 0;
    // The first byte picks the options; the rest is the effect and its headers.
    uint8_t mode = data[0];
    auto files = fuzz::splitInput(std::string_view(reinterpret_cast<const char*>(data) + 1, size - 1));
    auto dir = fuzz::writeFiles(files);
    xlate::CompileOptions options;
    options.useCache = false;
    options.inProcess = true;
    options.skipShaders = (mode & 1) != 0;
    options.keepValidPasses = (mode & 2) != 0;
    if (mode & 4) options.defines.push_back({"FUZZ_DEFINE", "1"});
    xlate::CompiledEffect effect;
    try {
        effect = xlate::compileEffectFile((dir / "main.fx").string(), options);
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
    // What compiled must be writable as a compiled-effect file and load back the same (the cache
    // and Effect::FromCompiledFile depend on it).
    try {
        std::string file = xlate::serializeEffect(effect);
        xlate::CompiledEffect back = xlate::deserializeEffect(file, "fuzz");
        if (xlate::serializeEffect(back) != file) {
            std::cerr << "compiled-effect file does not round-trip\n";
            std::abort();
        }
        (void)xlate::reflectionJson(effect);
    } catch (const std::exception& e) {
        std::cerr << "a compiled effect does not load back: " << e.what() << "\n";
        std::abort();
    }
    return 0;
}
