// See shader_valued_defaults.h.
#include "rewrite/shader_valued_defaults.h"

#include <algorithm>

#include "fx/text_util.h"

namespace fxport::xlate {

std::vector<TextEdit> shaderValuedDefaultsDropped(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const FxGlobal& g : syntax.globals) {
        const bool isStatic = std::find(g.modifiers.begin(), g.modifiers.end(), "static") != g.modifiers.end();
        if (isStatic || g.initializer.empty() || g.initializer.begin == 0 || !t[g.initializer.begin - 1].is("=")) continue;
        bool shader = false;
        // In a brace list only: `float4 f = sampler_state {...};` is refused ("cannot implicitly convert").
        const bool samplerInList = t[g.initializer.begin].is("{") && !iequals(g.type.substr(0, std::min<size_t>(g.type.size(), 7)), "sampler");
        for (size_t i = g.initializer.begin; i + 1 < g.initializer.end && !shader; ++i)
            shader = (t[i].is("compile") && t[i + 1].isIdent()) || (iequals(t[i].text, "CompileShader") && t[i + 1].is("(")) ||
                     (samplerInList && iequals(t[i].text, "sampler_state") && t[i + 1].is("{"));
        if (shader) edits.push_back({t[g.initializer.begin - 1].offset, t[g.initializer.end - 1].end, {}});
    }
    return edits;
}

}  // namespace fxport::xlate
