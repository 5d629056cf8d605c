// See one_component_types.h.
#include "rewrite/one_component_types.h"

#include <set>
#include <string>

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
    return edits;
}

}  // namespace fxport::xlate
