// `unsigned int`, `unsigned int2x2`, `unsigned T` (T a typedef of an int type): fxc's C-like
// spelling of uint types (vkd3d's unsigned file). glslang reserves the word. Before parsing, each
// `unsigned T` token pair becomes one token spelled as the uint type, and the text says so too.
// fxc refuses `unsigned` before a type that is not int-based (`unsigned uint`, a typedef of an
// array): so does this.
#pragma once

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "fx/fx_syntax.h"
#include "fx/lexer.h"

namespace fxport::xlate {

// Merges the pairs in `tokens` and appends the edits; the index of the first token fxc refuses and
// why, if any.
std::optional<std::pair<size_t, std::string>> mergeUnsignedTypes(std::vector<Token>& tokens, std::vector<TextEdit>& edits);

}  // namespace fxport::xlate
