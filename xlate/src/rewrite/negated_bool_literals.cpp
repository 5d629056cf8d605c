// See negated_bool_literals.h.
#include "rewrite/negated_bool_literals.h"

namespace fxport::xlate {

namespace {

// A `-` after one of these is a unary minus (not a subtraction).
bool beforeUnary(const Token& t) {
    if (t.kind != Token::Kind::Punct) return t.is("return");
    return !(t.is(")") || t.is("]"));
}

}  // namespace

std::vector<TextEdit> negatedBoolLiteralsAsInts(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const auto& f : syntax.functions)
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i)
            if (t[i].is("-") && (t[i + 1].is("true") || t[i + 1].is("false")) && i > 0 && beforeUnary(t[i - 1]))
                edits.push_back({t[i + 1].offset, t[i + 1].end, t[i + 1].is("true") ? "1" : "0"});
    return edits;
}

}  // namespace fxport::xlate
