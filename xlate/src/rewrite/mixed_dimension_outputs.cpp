// See mixed_dimension_outputs.h.
#include "rewrite/mixed_dimension_outputs.h"

#include <set>

#include "hlsl/call_arguments.h"
#include "hlsl/expression_types.h"
#include "hlsl/method_receivers.h"

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

// Whether a statement may start after token `before`: after `;`, a brace, a control statement's
// `)`, `else`, `do` or a case label. The rewrite turns the call into a block, a statement too.
bool startsStatement(const Token& before) {
    for (const char* s : {";", "{", "}", ")", "else", "do", ":"})
        if (before.is(s)) return true;
    return false;
}

}  // namespace

std::vector<TextEdit> mixedDimensionOutputs(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const auto& f : syntax.functions) {
        for (size_t i = f.body.begin + 1; i + 3 < f.body.end; ++i) {
            // `receiver . GetDimensions (` as a statement of its own, `) ;` after it; the receiver
            // any texture (`T`, `T[0]`, a parameter, `s.tex`).
            if (!t[i].is("GetDimensions") || !t[i - 1].is(".") || !t[i + 1].is("(")) continue;
            const auto receiver = methodReceiver(syntax, f, i - 1);
            if (!receiver) continue;
            const size_t start = receiver->begin;
            if (!startsStatement(t[start - 1])) continue;
            auto spans = callArgumentSpans(t, i + 1, f.body.end);
            if (spans.empty()) continue;
            const size_t close = spans.back().second;  // the ')'
            if (close + 1 >= f.body.end || !t[close + 1].is(";")) continue;
            // With a mip level (the first argument, an input) there is one more output, the levels.
            const size_t dims = dimensionCount(receiver->type);
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
            std::string temps, call = syntax.text(TokenSpan{start, i - 1}) + ".GetDimensions(", assign;
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
