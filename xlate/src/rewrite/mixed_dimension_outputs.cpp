// See mixed_dimension_outputs.h.
#include "rewrite/mixed_dimension_outputs.h"

#include <set>

#include "hlsl/call_arguments.h"
#include "hlsl/expression_types.h"

namespace fxport::xlate {

namespace {

// The out arguments of GetDimensions without a mip level for a texture type; 0 for other types.
size_t dimensionCount(const std::string& type) {
    const std::string t = type.substr(0, type.find('<'));
    if (t == "Texture1D") return 1;
    if (t == "Texture1DArray" || t == "Texture2D" || t == "TextureCube") return 2;
    if (t == "Texture2DArray" || t == "Texture3D" || t == "TextureCubeArray" || t == "Texture2DMS") return 3;
    if (t == "Texture2DMSArray") return 4;
    return 0;
}

}  // namespace

std::vector<TextEdit> mixedDimensionOutputs(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const auto& f : syntax.functions) {
        for (size_t i = f.body.begin + 1; i + 3 < f.body.end; ++i) {
            // `name . GetDimensions (` at the start of a statement, `) ;` after it.
            if (!t[i].is("GetDimensions") || !t[i - 1].is(".") || i < 2 || !t[i - 2].isIdent() || !t[i + 1].is("(")) continue;
            const size_t start = i - 2;
            if (!(t[start - 1].is(";") || t[start - 1].is("{") || t[start - 1].is("}"))) continue;
            auto spans = callArgumentSpans(t, i + 1, f.body.end);
            if (spans.empty()) continue;
            const size_t close = spans.back().second;  // the ')'
            if (close + 1 >= f.body.end || !t[close + 1].is(";")) continue;
            // With a mip level (the first argument, an input) there is one more output, the levels.
            const FxTexture* texture = syntax.findTexture(t[start].text);
            const size_t dims = texture ? dimensionCount(texture->type) : 0;
            if (dims == 0 || (spans.size() != dims && spans.size() != dims + 2)) continue;
            const size_t firstOut = spans.size() == dims ? 0 : 1;
            std::set<std::string> scalars;
            bool known = true;
            for (size_t k = firstOut; k < spans.size(); ++k) {
                const auto& [b, e] = spans[k];
                auto type = expressionType(syntax, f, b, e);
                if (!type || !type->isNumeric()) known = false;
                else scalars.insert(type->basic.scalar == "float" || type->basic.scalar == "half" ? "float" : type->basic.scalar);
            }
            // An argument of unknown type (expression_types.h misses `uint a, b;` locals) may be
            // either: temporaries are right for any numeric out argument.
            if (known && (scalars.size() < 2 || !scalars.count("float"))) continue;
            std::string temps, call = t[start].text + ".GetDimensions(", assign;
            for (size_t k = 0; k < spans.size(); ++k) {
                const std::string temp = "fxport_dim" + std::to_string(k);
                const std::string argument = syntax.text(TokenSpan{spans[k].first, spans[k].second});
                call += (k ? ", " : "") + (k < firstOut ? argument : temp);
                if (k < firstOut) continue;
                temps += (k > firstOut ? ", " : "uint ") + temp;
                assign += " " + argument + " = " + temp + ";";
            }
            edits.push_back({t[start].offset, t[close + 1].end, "{ " + temps + "; " + call + ");" + assign + " }"});
        }
    }
    return edits;
}

}  // namespace fxport::xlate
