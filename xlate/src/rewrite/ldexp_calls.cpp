// See ldexp_calls.h.
#include "rewrite/ldexp_calls.h"

#include "hlsl/call_arguments.h"
#include "hlsl/expression_types.h"

namespace fxport::xlate {

namespace {

// Scalars and vectors of one width (or a scalar beside a vector) whose types the tokens tell: their
// product is fxc's ldexp. Matrices, whose shapes fxc's rules for mixed operands decide, and what
// fxport cannot type keep glslang's ldexp (and its checks of the arguments).
bool spelledAsProduct(const EffectSyntax& syntax, const FxFunction& f, const std::vector<std::pair<size_t, size_t>>& args) {
    const auto x = expressionType(syntax, f, args[0].first, args[0].second);
    const auto e = expressionType(syntax, f, args[1].first, args[1].second);
    if (!x || !e || !x->isNumeric() || !e->isNumeric()) return false;
    if (x->keptMatrix || e->keptMatrix || x->basic.isMatrix || e->basic.isMatrix) return false;
    const int a = x->basic.columns, b = e->basic.columns;
    return a == b || a == 1 || b == 1;
}

}  // namespace

std::vector<TextEdit> ldexpAsExp2(const EffectSyntax& syntax) {
    std::vector<TextEdit> edits;
    if (syntax.findFunction("ldexp")) return edits;
    const auto& t = syntax.tokens;
    for (const auto& f : syntax.functions) {
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
            if (!t[i].is("ldexp") || !t[i + 1].is("(") || (i > 0 && t[i - 1].is("."))) continue;
            const auto args = callArgumentSpans(t, i + 1, f.body.end);
            if (args.size() != 2) continue;  // glslang names the wrong argument count
            if (!spelledAsProduct(syntax, f, args)) continue;
            const size_t comma = args[0].second, close = args[1].second;
            edits.push_back({t[i].offset, t[i + 1].end, "(("});
            edits.push_back({t[comma].offset, t[comma].end, ") * exp2("});
            edits.push_back({t[close].offset, t[close].end, "))"});
        }
    }
    return edits;
}

}  // namespace fxport::xlate
