// The arguments of a call in the token stream, as the token-level rewrites and checks split them.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

#include "fx/lexer.h"

namespace fxport::xlate {

// The [begin, end) token spans of the arguments of the call whose '(' is at `open` (commas inside
// nested brackets do not split); empty when the brackets do not close before `end`.
std::vector<std::pair<size_t, size_t>> callArgumentSpans(const std::vector<Token>& t, size_t open, size_t end);

}  // namespace fxport::xlate
