// See out_of_range_indices.h.
#include "rewrite/out_of_range_indices.h"

#include <cstdlib>

#include "hlsl/variable_declarations.h"

namespace fxport::xlate {

std::vector<TextEdit> outOfRangeIndicesDeferred(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    bool defined = false;
    for (const FxFunction& f : syntax.functions) {
        if (f.body.empty()) continue;
        for (size_t i = f.body.begin; i + 3 < f.body.end; ++i) {  // the body starts after its `{`
            // `name[N]` with the first index of name's first dimension a literal past its end.
            if (!t[i].isIdent() || t[i - 1].is(".") || !t[i + 1].is("[") || t[i + 2].kind != Token::Kind::Number || !t[i + 3].is("]")) continue;
            // `T name[N]` declares (another block may have declared `name` before with N elements,
            // and declaredVariable does not see block scopes: Wicked Engine's and Luna's shaders).
            if (t[i - 1].isIdent() && !t[i - 1].is("return") && !t[i - 1].is("else")) continue;
            const std::string& n = t[i + 2].text;
            if (n.find_first_not_of("0123456789") != std::string::npos) continue;  // 0x.., 1.5, 3u: left to glslang
            auto v = declaredVariable(syntax, f, t[i].text, i);
            if (!v || v->dims.empty() || v->dims[0] <= 0 || std::strtoll(n.c_str(), nullptr, 10) < v->dims[0]) continue;
            if (!defined) {  // one line, before the first function that needs it
                edits.push_back({t[f.declaration.begin].offset, t[f.declaration.begin].offset, "int fxport_index(int i) { return i; } "});
                defined = true;
            }
            edits.push_back({t[i + 2].offset, t[i + 2].offset, "fxport_index("});
            edits.push_back({t[i + 2].end, t[i + 2].end, ")"});
        }
    }
    return edits;
}

}  // namespace fxport::xlate
