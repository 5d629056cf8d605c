// [numthreads(x, y, z)] sizes written as constant expressions, as fxc takes them: `1 + 1`,
// `uint(1)`, a static int (its initial value), `max(128, 32)` (GameTechDev's OutdoorLightScattering
// defaults THREAD_GROUP_SIZE to that); vkd3d's numthreads pins which. Each size must be an integer:
// `float(1)` and `"1"` are refused, and so is what fxport cannot evaluate (`x++`), at the
// argument's file:line. glslang folds some of these and crashes on a static, so each evaluated
// size becomes the integer literal fxc computes.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

struct ThreadGroupSize {
    TokenSpan span;                 // the argument as written
    std::optional<long long> value;  // when it is an integer constant fxport evaluates
    std::string problem;            // why it is none, for the error
};

// The arguments of `f`'s [numthreads(...)] (its own attribute or its prototype's), split at
// top-level commas; empty when it has none.
std::vector<ThreadGroupSize> threadGroupSizes(const EffectSyntax& syntax, const FxFunction& f);

std::vector<TextEdit> threadGroupSizesAsLiterals(const EffectSyntax& syntax);

}  // namespace fxport::xlate
