// See refract_eta.h.
#include "rewrite/refract_eta.h"

#include "hlsl/call_arguments.h"
#include "hlsl/expression_types.h"

namespace fxport::xlate {

std::vector<TextEdit> refractVectorEta(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    if (syntax.findFunction("refract")) return edits;  // the effect's own refract: intrinsic_overrides.h
    for (const auto& f : syntax.functions) {
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
            if (!t[i].is("refract") || !t[i + 1].is("(") || (i > 0 && t[i - 1].is("."))) continue;
            auto spans = callArgumentSpans(t, i + 1, f.body.end);
            if (spans.size() != 3) continue;
            auto eta = expressionType(syntax, f, spans[2].first, spans[2].second);
            if (!eta || !eta->isNumeric() || eta->keptMatrix || eta->basic.isMatrix || eta->basic.columns < 2) continue;
            edits.push_back({t[spans[2].first].offset, t[spans[2].first].offset, "("});
            edits.push_back({t[spans[2].second - 1].end, t[spans[2].second - 1].end, ").x"});
        }
    }
    return edits;
}

}  // namespace fxport::xlate
