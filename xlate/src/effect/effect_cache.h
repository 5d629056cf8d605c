// Compiled-effect cache. A warm compile does no preprocessing: the key is the compiler version,
// the options (defines, include folders, techniques ...), where the effect lives and the raw bytes
// of the effect file (the entry is named and sealed by keyed hashes of it, keyed_hash.h); the entry lists every file the compile read through #include with
// a hash of its content (and every path the include search found empty), and is used only while
// all of them are unchanged. So a hit costs: read and hash the .fx, read the entry, re-hash its
// includes, parse the effect.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <string_view>

#include "fxport/xlate/compiled_effect.h"
#include "effect/keyed_hash.h"
#include "fx/preprocess.h"

namespace fxport::xlate {

std::string defaultCacheDir();
// The cache folder's secret (the file `secret` there, 32 random bytes made on first use, mode
// 0600). nullopt when it cannot be made, or is not a regular file of this user that only this user
// may read and write: then nothing is read from or written to the cache.
std::optional<CacheSecret> cacheSecret(const std::string& cacheDir);
// The whole entry for `key` whose text after its mac line is `afterMac` (dependencies, "=", body),
// and its file name (without ".fxeffect") in `name`. nullopt without a secret. For the fuzzer.
std::optional<std::string> sealCacheEntry(const std::string& cacheDir, const std::string& key, std::string_view afterMac,
                                          std::string* name = nullptr);
// The effect stored under `key`, if its include dependencies still hold; nullopt otherwise (also
// for a missing, stale or damaged entry, which the next store overwrites).
std::optional<CompiledEffect> loadCachedEffect(const std::string& cacheDir, const std::string& key);
// Best effort: a cache that cannot be written never fails a compile.
void storeCachedEffect(const std::string& cacheDir, const std::string& key, const std::vector<IncludeDependency>& dependencies,
                       const CompiledEffect& effect);

}  // namespace fxport::xlate
