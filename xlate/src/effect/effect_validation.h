// Compiled-effect files and cache entries are untrusted input (a damaged disk, an old or edited
// file): after the checksum, every size, offset, index and count the runtime will use is checked
// here, so a loaded CompiledEffect never makes it read or upload out of bounds.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "fxport/xlate/compiled_effect.h"

namespace fxport::xlate {

// What is wrong with `effect`, in one sentence; nullopt when it is consistent.
std::optional<std::string> findEffectInconsistency(const CompiledEffect& effect);

// `text` (a compiled-effect file) with its checksums recomputed, or unchanged when it is not a
// JSON object: lets the fuzzer reach the checks behind the checksum.
std::string resealEffectFile(std::string_view text);

}  // namespace fxport::xlate
