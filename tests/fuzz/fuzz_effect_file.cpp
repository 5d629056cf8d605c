// libFuzzer harness over compiled-effect loading: the bytes of a compiled-effect file (what
// `fxport compile` writes and Effect::FromCompiledFile reads) or of a compile-cache entry. Either
// loads into a CompiledEffect that passes validation, or fails with CompileError FX3101 (file) /
// nullopt (cache); nothing else, and nothing the runtime could index out of bounds with.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "effect_cache.h"
#include "fxport/xlate/effect_file.h"

using namespace fxport;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        xlate::CompiledEffect e = xlate::deserializeEffect(text, "fuzz.fxeffect");
        // What was accepted must be consistent: serialising and loading it again gives the same.
        std::string again = xlate::serializeEffect(e);
        xlate::CompiledEffect back = xlate::deserializeEffect(again, "fuzz-again.fxeffect");
        if (xlate::serializeEffect(back) != again) {
            std::cerr << "accepted compiled effect does not round-trip\n";
            std::abort();
        }
    } catch (const xlate::CompileError& e) {
        if (e.diagnostics().empty() || e.diagnostics().front().id != xlate::diag::kEffectFile) {
            std::cerr << "compiled-effect loading failed without FX3101\n";
            std::abort();
        }
    } catch (const std::exception& e) {
        std::cerr << "escaped exception (not a CompileError): " << e.what() << "\n";
        std::abort();
    }
    // The same bytes as a cache entry: used or not, never a crash or an escaped exception.
    static const std::string cacheDir = [] {
        auto d = std::filesystem::temp_directory_path() / ("fxport-fuzz-cache-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d.string();
    }();
    std::ofstream(cacheDir + "/entry.fxeffect", std::ios::binary).write(text.data(), static_cast<std::streamsize>(size));
    try {
        (void)xlate::loadCachedEffect(cacheDir, "entry");
    } catch (const std::exception& e) {
        std::cerr << "cache load threw: " << e.what() << "\n";
        std::abort();
    }
    return 0;
}
