// See one_component_types.h.
#include "rewrite/one_component_types.h"

#include <set>
#include <string>

#include "hlsl/expression_types.h"

namespace fxport::xlate {

namespace {

bool isScalarName(const std::string& s) {
    static const char* const kScalars[] = {"float",      "half",       "double",    "int",      "uint",     "bool", "dword",
                                           "min16float", "min10float", "min16int",  "min12int", "min16uint"};
    for (const char* k : kScalars)
        if (s == k) return true;
    return false;
}

// Parameter type tokens of functions that share their name with another function.
std::set<size_t> overloadedParameterTypes(const EffectSyntax& syntax) {
    std::set<size_t> out;
    for (const auto& f : syntax.functions) {
        int sameName = 0;
        for (const auto& g : syntax.functions) sameName += g.name == f.name;
        if (sameName > 1)
            for (const auto& p : f.parameters) out.insert(p.typeToken);
    }
    return out;
}

// The first token of the operand that `[` at `bracket` indexes, when it is a plain variable, a
// parenthesised expression or a call; `bracket` when it is anything else.
size_t indexedOperand(const std::vector<Token>& t, size_t begin, size_t bracket) {
    if (bracket <= begin) return bracket;
    const size_t last = bracket - 1;
    if (t[last].isIdent()) return last > begin && t[last - 1].is(".") ? bracket : last;
    if (!t[last].is(")")) return bracket;
    int depth = 0;
    for (size_t k = last + 1; k-- > begin;) {
        if (t[k].is(")")) ++depth;
        else if (t[k].is("(") && --depth == 0) {
            const bool call = k > begin && t[k - 1].isIdent() && !t[k - 1].is("return") && !t[k - 1].is("else") && !t[k - 1].is("case");
            if (call) return k - 1 > begin && t[k - 2].is(".") ? bracket : k - 1;
            return k;
        }
    }
    return bracket;
}

// `v[0]` of a one-component vector (vkd3d's ternary indexes `(cond ? a : b)[0]` of float1s): once
// the vector is a scalar to glslang, it cannot be indexed ("left of '[' is not of type array"); a
// scalar is its own component 0.
void dropIndexesOfOneComponentVectors(const EffectSyntax& syntax, std::vector<TextEdit>& edits) {
    const std::vector<Token>& t = syntax.tokens;
    for (const auto& f : syntax.functions)
        for (size_t i = f.body.begin + 1; i + 2 < f.body.end; ++i) {
            if (!t[i].is("[") || !t[i + 1].is("0") || !t[i + 2].is("]")) continue;
            const size_t operand = indexedOperand(t, f.body.begin, i);
            if (operand == i) continue;
            auto type = expressionType(syntax, f, operand, i);
            if (type && type->isNumeric() && type->vector1 && !type->keptMatrix) edits.push_back({t[i].offset, t[i + 2].end, ""});
        }
}

}  // namespace

std::vector<TextEdit> respellOneComponentVectors(const EffectSyntax& syntax) {
    const std::vector<Token>& tokens = syntax.tokens;
    const std::set<size_t> keep = overloadedParameterTypes(syntax);
    std::vector<TextEdit> edits;
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (keep.count(i)) continue;
        const Token& t = tokens[i];
        if (!t.isIdent() || t.text.size() < 2 || t.text.back() != '1') continue;
        std::string scalar = t.text.substr(0, t.text.size() - 1);
        if (!isScalarName(scalar)) continue;
        if (i > 0 && tokens[i - 1].is(".")) continue;  // a member that happens to be named `float1`
        edits.push_back({t.offset, t.end, scalar});
    }
    dropIndexesOfOneComponentVectors(syntax, edits);
    return edits;
}

}  // namespace fxport::xlate
