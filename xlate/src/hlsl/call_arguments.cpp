// See call_arguments.h.
#include "hlsl/call_arguments.h"

namespace fxport::xlate {

std::vector<std::pair<size_t, size_t>> callArgumentSpans(const std::vector<Token>& t, size_t open, size_t end) {
    std::vector<std::pair<size_t, size_t>> out;
    int depth = 0;
    size_t start = open + 1;
    for (size_t j = open; j < end; ++j) {
        if (t[j].is("(") || t[j].is("[") || t[j].is("{")) {
            ++depth;
        } else if (t[j].is(")") || t[j].is("]") || t[j].is("}")) {
            if (--depth == 0) {
                if (j > start) out.push_back({start, j});
                return out;
            }
        } else if (depth == 1 && t[j].is(",")) {
            out.push_back({start, j});
            start = j + 1;
        }
    }
    return {};
}

}  // namespace fxport::xlate
