// fxc's refusal of a constant index past the end of an array in code that runs (error X3504),
// checked on the legalised module, where dead code is gone (rewrite/out_of_range_indices.h lets
// glslang take such an index in the first place).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fxport::xlate {

struct IndexPastEnd {
    std::int64_t index = 0;
    std::int64_t length = 0;
};

// The first access chain into an array with a constant index outside it; none when there is none.
std::optional<IndexPastEnd> constantIndexPastArrayEnd(const std::vector<std::uint32_t>& words);

// The line of `source` (1-based) where the rewrite deferred literal index `index`, 0 if none.
int deferredIndexLine(const std::string& source, std::int64_t index);

}  // namespace fxport::xlate
