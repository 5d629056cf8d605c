// See matrix_constructor_arguments.h.
#include "rewrite/matrix_constructor_arguments.h"

#include "hlsl/call_arguments.h"
#include "hlsl/expression_types.h"

namespace fxport::xlate {

namespace {

// `a`, `s.m`, `arr[2].m`: names, members and constant indices only.
bool isPlainPath(const std::vector<Token>& t, size_t b, size_t e) {
    if (b >= e || !t[b].isIdent()) return false;
    for (size_t i = b + 1; i < e; ++i) {
        if (t[i].is(".") && i + 1 < e && t[i + 1].isIdent()) ++i;
        else if (t[i].is("[") && i + 2 < e && t[i + 1].kind == Token::Kind::Number && t[i + 2].is("]")) i += 2;
        else return false;
    }
    return true;
}

std::string spelled(const std::vector<Token>& t, size_t b, size_t e) {
    std::string s;
    for (size_t i = b; i < e; ++i) s += t[i].text;
    return s;
}

}  // namespace

std::vector<TextEdit> matrixConstructorArgumentsAsRows(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const auto& f : syntax.functions) {
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
            if (!t[i].isIdent() || !t[i + 1].is("(") || (i > 0 && t[i - 1].is("."))) continue;
            if (!describeBasicType(syntax.resolveType(t[i].text)).ok) continue;
            auto spans = callArgumentSpans(t, i + 1, f.body.end);
            if (spans.size() < 2) continue;
            for (const auto& [b, e] : spans) {
                if (!isPlainPath(t, b, e)) continue;
                auto type = expressionType(syntax, f, b, e);
                if (!type || !type->isNumeric() || type->keptMatrix || !type->basic.isMatrix || type->basic.rows < 2 || type->basic.columns < 2)
                    continue;
                const std::string name = spelled(t, b, e);
                std::string rows;
                for (int r = 0; r < type->basic.rows; ++r) rows += (r ? ", " : "") + name + "[" + std::to_string(r) + "]";
                edits.push_back({t[b].offset, t[e - 1].end, rows});
            }
        }
    }
    return edits;
}

}  // namespace fxport::xlate
