#include "effect/effect_cache.h"

#include <fcntl.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>
#include <string_view>

#include "fxport/xlate/effect_file.h"
#include "fx/input_limits.h"
#include "effect/keyed_hash.h"
#include "fx/text_util.h"

namespace fs = std::filesystem;

namespace fxport::xlate {

namespace {

// Entry layout: a header naming its key and the MAC of the rest, the dependencies, then the
// serialised effect (the body).
//   fxport-cache 3
//   key <keyed hash of the whole key>     an entry copied under another name is refused
//   mac <keyed hash of the key line and everything after the mac line>   checked before anything else is read
//   + <content hash> <absolute path>      a file read through #include
//   - <absolute path>                     a path the include search found empty
//   =
//   <compiled effect, JSON>
// Both hashes are keyed with the cache's secret (keyed_hash.h), so nobody without it can write an
// entry that is used, or make two keys collide. An entry is read only up to
// limits::kMaxEffectFileBytes; one refused for any reason is overwritten by the compile that follows.
constexpr std::string_view kMagic = "fxport-cache 3\n";
constexpr const char* kSecretFile = "secret";
constexpr size_t kSecretBytes = 32;

// The value of header line `name` ("key abc" -> "abc"), removed from `rest`; nullopt when the next
// line is another.
std::optional<std::string_view> takeField(std::string_view& rest, std::string_view name) {
    size_t end = rest.find('\n');
    if (end == std::string_view::npos || rest.substr(0, name.size() + 1) != std::string(name) + " ") return std::nullopt;
    std::string_view value = rest.substr(name.size() + 1, end - name.size() - 1);
    rest.remove_prefix(end + 1);
    return value;
}

std::string folderOf(const std::string& cacheDir) { return cacheDir.empty() ? defaultCacheDir() : cacheDir; }

bool dependencyHolds(std::string_view line) {
    if (line.size() < 3 || line[1] != ' ') return false;
    if (line[0] == '-') {
        std::error_code ec;
        return !fs::exists(fs::path(std::string(line.substr(2))), ec) && !ec;
    }
    if (line[0] != '+') return false;
    size_t space = line.find(' ', 2);
    if (space == std::string_view::npos) return false;
    auto text = readFile(std::string(line.substr(space + 1)), limits::kMaxFileBytes);  // no include is larger
    return text && contentHash(*text) == line.substr(2, space - 2);
}

// Reads the secret from an open file: only a regular file of this user that nobody else may read
// or write, of exactly kSecretBytes.
std::optional<CacheSecret> readSecret(int fd) {
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode) || st.st_uid != ::geteuid() || (st.st_mode & 077) != 0 ||
        st.st_size != static_cast<off_t>(kSecretBytes))
        return std::nullopt;
    std::uint8_t bytes[kSecretBytes];
    if (::read(fd, bytes, kSecretBytes) != static_cast<ssize_t>(kSecretBytes)) return std::nullopt;
    CacheSecret secret;
    std::memcpy(secret.first.data(), bytes, 16);
    std::memcpy(secret.second.data(), bytes + 16, 16);
    return secret;
}

// Makes the secret file: kSecretBytes from the kernel's random source, mode 0600, never through a
// link, never over an existing file (two compiles racing: the second reads the first's).
bool createSecret(const std::string& path) {
    std::uint8_t bytes[kSecretBytes];
    if (::getrandom(bytes, kSecretBytes, 0) != static_cast<ssize_t>(kSecretBytes)) return false;
    std::string tmp = path + ".tmp" + std::to_string(::getpid());
    int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0) return false;
    bool written = ::write(fd, bytes, kSecretBytes) == static_cast<ssize_t>(kSecretBytes);
    written = ::close(fd) == 0 && written;
    // link() fails when another compile made the file first: then that one is used.
    bool linked = written && ::link(tmp.c_str(), path.c_str()) == 0;
    ::unlink(tmp.c_str());
    return linked || errno == EEXIST;
}

}  // namespace

std::optional<CacheSecret> cacheSecret(const std::string& cacheDir) {
    std::string path = folderOf(cacheDir) + "/" + kSecretFile;
    for (int attempt = 0; attempt < 2; ++attempt) {
        int fd = ::open(path.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
        if (fd >= 0) {
            auto secret = readSecret(fd);
            ::close(fd);
            return secret;
        }
        if (errno != ENOENT) return std::nullopt;
        std::error_code ec;
        fs::create_directories(folderOf(cacheDir), ec);
        if (!createSecret(path)) return std::nullopt;
    }
    return std::nullopt;
}

std::string defaultCacheDir() {
    if (const char* d = std::getenv("FXPORT_CACHE_DIR"); d && *d) return d;
    if (const char* x = std::getenv("XDG_CACHE_HOME"); x && *x) return std::string(x) + "/fxport";
    if (const char* h = std::getenv("HOME"); h && *h) return std::string(h) + "/.cache/fxport";
    return ".fxport-cache";
}

std::optional<CompiledEffect> loadCachedEffect(const std::string& cacheDir, const std::string& key) {
    auto secret = cacheSecret(cacheDir);
    if (!secret) return std::nullopt;  // no secret of our own: no cache
    const std::string name = keyedHash(*secret, key);
    auto text = readFile(folderOf(cacheDir) + "/" + name + ".fxeffect", limits::kMaxEffectFileBytes);
    if (!text) return std::nullopt;
    std::string_view rest(*text);
    if (rest.substr(0, kMagic.size()) != kMagic) return std::nullopt;
    rest.remove_prefix(kMagic.size());
    auto storedKey = takeField(rest, "key");
    auto mac = takeField(rest, "mac");
    if (!storedKey || *storedKey != name || !mac) return std::nullopt;
    // Damaged, padded or written by someone without the secret: nothing of it is used (its
    // dependency paths are not even opened).
    if (keyedHash(*secret, "key " + name + "\n" + std::string(rest)) != *mac) return std::nullopt;
    for (;;) {
        size_t end = rest.find('\n');
        if (end == std::string_view::npos) return std::nullopt;
        std::string_view line = rest.substr(0, end);
        rest.remove_prefix(end + 1);
        if (line == "=") break;
        if (!dependencyHolds(line)) return std::nullopt;  // an include changed: recompile
    }
    try {
        return deserializeEffect(rest, name);
    } catch (const std::exception&) {
        return std::nullopt;  // stale or damaged entry: recompile and overwrite
    }
}

std::optional<std::string> sealCacheEntry(const std::string& cacheDir, const std::string& key, std::string_view afterMac,
                                          std::string* name) {
    auto secret = cacheSecret(cacheDir);
    if (!secret) return std::nullopt;
    std::string keyName = keyedHash(*secret, key);
    if (name) *name = keyName;
    std::string keyLine = "key " + keyName + "\n";
    return std::string(kMagic) + keyLine + "mac " + keyedHash(*secret, keyLine + std::string(afterMac)) + "\n" + std::string(afterMac);
}

void storeCachedEffect(const std::string& cacheDir, const std::string& key, const std::vector<IncludeDependency>& dependencies,
                       const CompiledEffect& effect) {
    std::string rest;
    for (const auto& d : dependencies) {
        if (d.path.find('\n') != std::string::npos) return;  // cannot be written down: do not cache
        rest += d.hash.empty() ? "- " + d.path + "\n" : "+ " + d.hash + " " + d.path + "\n";
    }
    rest += "=\n";
    rest += serializeEffect(effect, /*compact=*/true);
    std::string name;
    auto entry = sealCacheEntry(cacheDir, key, rest, &name);
    if (!entry || entry->size() > limits::kMaxEffectFileBytes) return;  // no secret, or would never be read back
    std::string path = folderOf(cacheDir) + "/" + name + ".fxeffect";
    std::error_code ec;
    fs::create_directories(fs::path(path).parent_path(), ec);
    // Write then rename, so a concurrent reader never sees half a file.
    std::string tmp = path + ".tmp" + std::to_string(std::random_device{}());
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) return;
        out.write(entry->data(), static_cast<std::streamsize>(entry->size()));
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
