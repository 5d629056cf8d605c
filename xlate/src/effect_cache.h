// Compiled-effect cache. A warm compile does no preprocessing: the key is a hash of the compiler
// version, the options (defines, include folders, techniques ...), where the effect lives and the
// raw bytes of the effect file; the entry lists every file the compile read through #include with
// a hash of its content (and every path the include search found empty), and is used only while
// all of them are unchanged. So a hit costs: read and hash the .fx, read the entry, re-hash its
// includes, parse the effect.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fxport/xlate/compiled_effect.h"
#include "preprocess.h"

namespace fxport::xlate {

std::string defaultCacheDir();
// The effect stored under `key`, if its include dependencies still hold; nullopt otherwise (also
// for a missing, stale or damaged entry, which the next store overwrites).
std::optional<CompiledEffect> loadCachedEffect(const std::string& cacheDir, const std::string& key);
// Best effort: a cache that cannot be written never fails a compile.
void storeCachedEffect(const std::string& cacheDir, const std::string& key, const std::vector<IncludeDependency>& dependencies,
                       const CompiledEffect& effect);

}  // namespace fxport::xlate
