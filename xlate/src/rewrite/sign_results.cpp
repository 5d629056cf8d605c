// See sign_results.h.
#include "rewrite/sign_results.h"

#include "hlsl/call_arguments.h"
#include "hlsl/expression_types.h"

namespace fxport::xlate {

std::vector<TextEdit> signResultsAsInts(const EffectSyntax& syntax) {
    std::vector<TextEdit> edits;
    if (syntax.findFunction("sign")) return edits;
    const auto& t = syntax.tokens;
    for (const auto& f : syntax.functions) {
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
            if (!t[i].is("sign") || !t[i + 1].is("(") || (i > 0 && t[i - 1].is("."))) continue;
            const auto args = callArgumentSpans(t, i + 1, f.body.end);
            if (args.size() != 1) continue;
            const auto type = expressionType(syntax, f, args[0].first, args[0].second);
            if (!type || !type->isNumeric() || type->keptMatrix || type->basic.isMatrix) continue;
            BasicType result = type->basic;
            result.scalar = "int";
            edits.push_back({t[i].offset, t[i].offset, "((" + glslangSpelling(result) + ")"});
            edits.push_back({t[args[0].second].end, t[args[0].second].end, ")"});
        }
    }
    return edits;
}

}  // namespace fxport::xlate
