// See switch_labels.h.
#include "rewrite/switch_labels.h"

#include <cmath>
#include <cstdlib>

#include "hlsl/expression_types.h"
#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

// `2.1f`, `0.9`, `1e3`, `3.h`: a float literal (no hex: `0xF` is an int).
bool isFloatLiteral(const Token& t) {
    if (t.kind != Token::Kind::Number || (t.text.size() > 1 && (t.text[1] == 'x' || t.text[1] == 'X'))) return false;
    return t.text.find_first_of(".eEfFhH") != std::string::npos;
}

// The integer a float literal truncates to, spelled back (the sign stays on its own token).
std::string truncated(const std::string& literal) {
    std::string digits = literal;
    while (!digits.empty() && std::string("fFhHlL").find(digits.back()) != std::string::npos) digits.pop_back();
    double v = std::trunc(std::strtod(digits.c_str(), nullptr));
    if (!(v >= 0 && v <= 4294967295.0)) return literal;  // out of range: left for glslang to refuse
    return std::to_string(static_cast<unsigned long long>(v));
}

// The selector `( ... )` of a `switch` at token `i`: its first and one-past-last token.
bool selectorAt(const std::vector<Token>& t, size_t i, size_t end, size_t& begin, size_t& close) {
    if (!t[i].is("switch") || i + 1 >= end || !t[i + 1].is("(")) return false;
    int depth = 0;
    for (size_t k = i + 1; k < end; ++k) {
        if (t[k].is("(")) ++depth;
        else if (t[k].is(")") && --depth == 0) {
            begin = i + 2;
            close = k;
            return close > begin;
        }
    }
    return false;
}

bool isFloatScalar(const EffectSyntax& syntax, const FxFunction& f, size_t begin, size_t end) {
    auto type = expressionType(syntax, f, begin, end);
    return type && type->isNumeric() && !type->basic.isMatrix && type->basic.columns == 1 &&
           (type->basic.scalar == "float" || type->basic.scalar == "half" || type->basic.scalar == "double");
}

class SwitchSelectorRules : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& e : compiledEntries()) {
            if (e.profile.major >= 4) continue;
            for (const FxFunction* f : reachableFrom(*e.function))
                for (size_t i = f->body.begin, b = 0, c = 0; i < f->body.end; ++i)
                    if (selectorAt(t_, i, f->body.end, b, c) && isFloatScalar(syntax_, *f, b, c))
                        report("a switch on a float value is not supported in " + e.profile.name + " (fxc takes integer selectors only below shader model 4)", i);
        }
    }
};

}  // namespace

std::vector<TextEdit> switchLabelsAsIntegers(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const auto& f : syntax.functions) {
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
            size_t label = i + 1 < f.body.end && t[i + 1].is("-") ? i + 2 : i + 1;
            if (t[i].is("case") && label < f.body.end && isFloatLiteral(t[label]))
                edits.push_back({t[label].offset, t[label].end, truncated(t[label].text)});
            size_t b = 0, c = 0;
            if (selectorAt(t, i, f.body.end, b, c) && isFloatScalar(syntax, f, b, c)) {
                edits.push_back({t[b].offset, t[b].offset, "int("});
                edits.push_back({t[c - 1].end, t[c - 1].end, ")"});
            }
        }
    }
    return edits;
}

std::vector<std::pair<size_t, Diagnostic>> findSwitchSelectorErrors(const EffectSyntax& syntax, const SourceMap& map) {
    SwitchSelectorRules check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
