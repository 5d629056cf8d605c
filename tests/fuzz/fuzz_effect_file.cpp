// libFuzzer harness over compiled-effect loading: the bytes of a compiled-effect file (what
// `fxport compile` writes and Effect::FromCompiledFile reads, and the body of a cache entry). It
// loads into a CompiledEffect that passes validation, or fails with CompileError FX3101; nothing
// else, and nothing the runtime could index out of bounds with. (Cache entries as a whole, with
// their keyed MAC and dependencies: fuzz_cache_entry.cpp.)
#include <cstdint>
#include <cstdlib>
#include <exception>
#include <iostream>
#include <string>

#include "effect/effect_validation.h"
#include "fxport/xlate/effect_file.h"

using namespace fxport;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    // An odd first byte re-seals the rest (checksums recomputed), so mutations reach the checks
    // behind the checksum; an even one loads the bytes as they are.
    if (size < 1) return 0;
    std::string resealed;
    std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
    if (data[0] & 1) text = resealed = xlate::resealEffectFile(text);
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
    return 0;
}
