// libFuzzer harness over the compile cache's reader (effect_cache.h): the bytes of an entry are
// written where the cache looks for key "fuzz-key" and read back with loadCachedEffect. An odd mode
// byte seals the rest with the cache's secret first (the text after the mac line: dependency
// lines, "=", the compiled effect), so mutations reach the dependency and JSON checks behind the
// keyed MAC; an even one writes the bytes as they are (what someone without the secret can do).
// A finding: a crash or sanitizer report, an escaped exception, an accepted effect that does not
// round-trip, or (unsealed) an entry accepted at all.
#include <unistd.h>

#include <cstdint>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>

#include "effect/effect_cache.h"
#include "fxport/xlate/effect_file.h"

using namespace fxport;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    if (size < 1) return 0;
    static const std::string cacheDir = [] {
        auto d = std::filesystem::temp_directory_path() / ("fxport-fuzz-cache-entry-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d.string();
    }();
    static const std::string key = "fuzz-key";
    std::string_view bytes(reinterpret_cast<const char*>(data) + 1, size - 1);
    const bool sealed = (data[0] & 1) != 0;
    std::string name;
    auto entry = xlate::sealCacheEntry(cacheDir, key, bytes, &name);
    if (!entry) {
        std::cerr << "the cache has no secret in " << cacheDir << "\n";
        std::abort();
    }
    if (!sealed) *entry = bytes;
    std::ofstream(cacheDir + "/" + name + ".fxeffect", std::ios::binary | std::ios::trunc)
        .write(entry->data(), static_cast<std::streamsize>(entry->size()));
    std::optional<xlate::CompiledEffect> effect;
    try {
        effect = xlate::loadCachedEffect(cacheDir, key);
    } catch (const std::exception& e) {
        std::cerr << "cache load threw: " << e.what() << "\n";
        std::abort();
    }
    if (!effect) return 0;
    if (!sealed) {
        std::cerr << "an entry not sealed with the secret was used\n";
        std::abort();
    }
    try {
        std::string file = xlate::serializeEffect(*effect);
        if (xlate::serializeEffect(xlate::deserializeEffect(file, "fuzz-again")) != file) {
            std::cerr << "accepted cache entry does not round-trip\n";
            std::abort();
        }
    } catch (const std::exception& e) {
        std::cerr << "accepted cache entry does not load back: " << e.what() << "\n";
        std::abort();
    }
    return 0;
}
