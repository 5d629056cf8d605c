// Compiled-effect cache: one file per key (hash of compiler version + preprocessed source + options)
// holding the serialised effect. A warm compile is: read the .fx, preprocess, hash, load JSON.
#pragma once

#include <optional>
#include <string>

#include "fxport/xlate/compiled_effect.h"

namespace fxport::xlate {

std::string defaultCacheDir();
std::optional<CompiledEffect> loadCachedEffect(const std::string& cacheDir, const std::string& key);
// Best effort: a cache that cannot be written never fails a compile.
void storeCachedEffect(const std::string& cacheDir, const std::string& key, const CompiledEffect& effect);

}  // namespace fxport::xlate
