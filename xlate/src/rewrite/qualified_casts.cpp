// See qualified_casts.h.
#include "rewrite/qualified_casts.h"

namespace fxport::xlate {

namespace {

// The token after a type that starts at `i` (a name, or a name with a `<...>` argument list), or
// `i` itself where no type starts.
size_t pastType(const std::vector<Token>& t, size_t i) {
    if (i >= t.size() || !t[i].isIdent()) return i;
    size_t k = i + 1;
    if (k < t.size() && t[k].is("<")) {
        while (k < t.size() && !t[k].is(">") && !t[k].is(")") && !t[k].is(";")) ++k;
        if (k >= t.size() || !t[k].is(">")) return i;
        ++k;
    }
    return k;
}

}  // namespace

std::vector<TextEdit> castQualifiersDropped(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const auto& f : syntax.functions)
        for (size_t i = f.body.begin; i + 3 < f.body.end; ++i) {
            if (!t[i].is("(") || !t[i + 1].is("const")) continue;
            size_t close = pastType(t, i + 2);
            // `( const TYPE )` followed by an operand: a cast (a declaration would name something).
            if (close == i + 2 || close >= f.body.end || !t[close].is(")")) continue;
            edits.push_back({t[i + 1].offset, t[i + 1].end, ""});
        }
    return edits;
}

}  // namespace fxport::xlate
