#include "effect_cache.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>

#include "fxport/xlate/effect_file.h"
#include "text_util.h"

namespace fs = std::filesystem;

namespace fxport::xlate {

std::string defaultCacheDir() {
    if (const char* d = std::getenv("FXPORT_CACHE_DIR"); d && *d) return d;
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::string(x) + "/fxport";
    if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.cache/fxport";
    return ".fxport-cache";
}

static std::string entryPath(const std::string& cacheDir, const std::string& key) {
    return (cacheDir.empty() ? defaultCacheDir() : cacheDir) + "/" + key + ".fxeffect";
}

std::optional<CompiledEffect> loadCachedEffect(const std::string& cacheDir, const std::string& key) {
    auto text = readFile(entryPath(cacheDir, key));
    if (!text) return std::nullopt;
    try {
        return deserializeEffect(*text, key);
    } catch (const std::exception&) {
        return std::nullopt;  // stale or damaged entry: recompile and overwrite
    }
}

void storeCachedEffect(const std::string& cacheDir, const std::string& key, const CompiledEffect& effect) {
    std::string path = entryPath(cacheDir, key);
    std::error_code ec;
    fs::create_directories(fs::path(path).parent_path(), ec);
    // Write then rename, so a concurrent reader never sees half a file.
    std::string tmp = path + ".tmp" + std::to_string(std::random_device{}());
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) return;
        out << serializeEffect(effect);
        if (!out) return;
    }
    fs::rename(tmp, path, ec);
    if (ec) fs::remove(tmp, ec);
}

}  // namespace fxport::xlate
