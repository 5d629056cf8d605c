#include "effect_cache.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <string_view>

#include "fxport/xlate/effect_file.h"
#include "input_limits.h"
#include "text_util.h"

namespace fs = std::filesystem;

namespace fxport::xlate {

namespace {

// Entry layout: a header naming its key, the checksum of the body and the dependencies, then the
// serialised effect (the body).
//   fxport-cache 2
//   key <key>                             the whole key: an entry copied under another name is refused
//   sum <content hash of the body>        checked before the body is parsed
//   + <content hash> <absolute path>      a file read through #include
//   - <absolute path>                     a path the include search found empty
//   =
//   <compiled effect, JSON>
// An entry is read only up to limits::kMaxEffectFileBytes; one refused for any reason is
// overwritten by the compile that follows.
constexpr std::string_view kMagic = "fxport-cache 2\n";

// The value of header line `name` ("key abc" -> "abc"), removed from `rest`; nullopt when the next
// line is another.
std::optional<std::string_view> takeField(std::string_view& rest, std::string_view name) {
    size_t end = rest.find('\n');
    if (end == std::string_view::npos || rest.substr(0, name.size() + 1) != std::string(name) + " ") return std::nullopt;
    std::string_view value = rest.substr(name.size() + 1, end - name.size() - 1);
    rest.remove_prefix(end + 1);
    return value;
}

std::string entryPath(const std::string& cacheDir, const std::string& key) {
    return (cacheDir.empty() ? defaultCacheDir() : cacheDir) + "/" + key + ".fxeffect";
}

bool dependencyHolds(std::string_view line) {
    if (line.size() < 3 || line[1] != ' ') return false;
    if (line[0] == '-') {
        std::error_code ec;
        return !fs::exists(fs::path(std::string(line.substr(2))), ec) && !ec;
    }
    if (line[0] != '+') return false;
    size_t space = line.find(' ', 2);
    if (space == std::string_view::npos) return false;
    auto text = readFile(std::string(line.substr(space + 1)));
    return text && contentHash(*text) == line.substr(2, space - 2);
}

}  // namespace

std::string defaultCacheDir() {
    if (const char* d = std::getenv("FXPORT_CACHE_DIR"); d && *d) return d;
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::string(x) + "/fxport";
    if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.cache/fxport";
    return ".fxport-cache";
}

std::optional<CompiledEffect> loadCachedEffect(const std::string& cacheDir, const std::string& key) {
    auto text = readFile(entryPath(cacheDir, key), limits::kMaxEffectFileBytes);
    if (!text) return std::nullopt;
    std::string_view rest(*text);
    if (rest.substr(0, kMagic.size()) != kMagic) return std::nullopt;
    rest.remove_prefix(kMagic.size());
    auto storedKey = takeField(rest, "key");
    auto sum = takeField(rest, "sum");
    if (!storedKey || *storedKey != key || !sum) return std::nullopt;
    for (;;) {
        size_t end = rest.find('\n');
        if (end == std::string_view::npos) return std::nullopt;
        std::string_view line = rest.substr(0, end);
        rest.remove_prefix(end + 1);
        if (line == "=") break;
        if (!dependencyHolds(line)) return std::nullopt;  // an include changed: recompile
    }
    if (contentHash(rest) != *sum) return std::nullopt;  // damaged or padded: recompile and overwrite
    try {
        return deserializeEffect(rest, key);
    } catch (const std::exception&) {
        return std::nullopt;  // stale or damaged entry: recompile and overwrite
    }
}

void storeCachedEffect(const std::string& cacheDir, const std::string& key, const std::vector<IncludeDependency>& dependencies,
                       const CompiledEffect& effect) {
    std::string body = serializeEffect(effect, /*compact=*/true);
    if (body.size() > limits::kMaxEffectFileBytes) return;  // would never be read back
    std::string entry(kMagic);
    entry += "key " + key + "\nsum " + contentHash(body) + "\n";
    for (const auto& d : dependencies) {
        if (d.path.find('\n') != std::string::npos) return;  // cannot be written down: do not cache
        entry += d.hash.empty() ? "- " + d.path + "\n" : "+ " + d.hash + " " + d.path + "\n";
    }
    entry += "=\n";
    entry += body;
    std::string path = entryPath(cacheDir, key);
    std::error_code ec;
    fs::create_directories(fs::path(path).parent_path(), ec);
    // Write then rename, so a concurrent reader never sees half a file.
    std::string tmp = path + ".tmp" + std::to_string(std::random_device{}());
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) return;
        out.write(entry.data(), static_cast<std::streamsize>(entry.size()));
        if (!out) {
            out.close();
            fs::remove(tmp, ec);
            return;
        }
    }
    fs::rename(tmp, path, ec);
    if (ec) fs::remove(tmp, ec);
}

}  // namespace fxport::xlate
