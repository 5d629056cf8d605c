// See intrinsic_spellings.h.
#include "rewrite/intrinsic_spellings.h"

#include <utility>

namespace fxport::xlate {

std::vector<TextEdit> intrinsicsAsGlslangSpellsThem(const EffectSyntax& syntax) {
    static const std::pair<const char*, const char*> kSpellings[] = {{"EvaluateAttributeCentroid", "EvaluateAttributeAtCentroid"}};
    std::vector<TextEdit> edits;
    const std::vector<Token>& t = syntax.tokens;
    for (const auto& [d3d, glslang] : kSpellings) {
        if (syntax.findFunction(d3d)) continue;
        for (size_t i = 0; i + 1 < t.size(); ++i)
            if (t[i].text == d3d && t[i + 1].is("(") && (i == 0 || !t[i - 1].is(".")))
                edits.push_back({t[i].offset, t[i].end, glslang});
    }
    return edits;
}

}  // namespace fxport::xlate
