// See variable_declarations.h.
#include "hlsl/variable_declarations.h"

#include <algorithm>
#include <cstdlib>

#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

std::unordered_map<std::string, std::vector<size_t>> declarationSites(const std::vector<Token>& t, TokenSpan body) {
    std::unordered_map<std::string, std::vector<size_t>> sites;
    for (size_t i = body.begin + 1; i < body.end && i + 1 < t.size(); ++i)
        if (t[i].isIdent() && t[i - 1].isIdent() && !t[i + 1].is("(")) sites[t[i].text].push_back(i);
    return sites;
}

std::optional<DeclaredVariable> declaredVariable(const EffectSyntax& syntax, const FxFunction& f, const std::string& name, size_t at) {
    const auto& t = syntax.tokens;
    static const std::vector<size_t> kNone;
    auto found = f.declarationSites.find(name);
    const std::vector<size_t>& sites = found != f.declarationSites.end() ? found->second : kNone;
    // The nearest site before `at` whose type is numeric or a struct, as a backward scan finds it.
    for (auto s = std::lower_bound(sites.begin(), sites.end(), std::min(at, f.body.end)); s != sites.begin();) {
        const size_t i = *--s;
        const std::string& type = t[i - 1].text;
        if (!describeBasicType(syntax.resolveType(type)).ok && !syntax.findStruct(syntax.resolveType(type))) continue;
        DeclaredVariable d{type, {}};
        for (size_t j = i + 1; j + 2 < f.body.end && t[j].is("["); j += 3) {
            if (t[j + 1].kind != Token::Kind::Number || !t[j + 2].is("]")) return std::nullopt;
            d.dims.push_back(std::atoi(t[j + 1].text.c_str()));
        }
        return d;
    }
    for (const auto& p : f.parameters)
        if (p.name == name) return DeclaredVariable{p.type, p.arrayDims};
    for (const auto& g : syntax.globals)
        if (g.name == name) return DeclaredVariable{g.type, g.arrayDims};
    return std::nullopt;
}

bool isVectorUniform(const EffectSyntax& syntax, const FxGlobal& g) {
    if (std::find(g.modifiers.begin(), g.modifiers.end(), "static") != g.modifiers.end() || !g.arrayDims.empty() || g.isStringParameter) return false;
    if (std::find(g.modifiers.begin(), g.modifiers.end(), "groupshared") != g.modifiers.end()) return false;
    if (syntax.resolveType(g.type) != g.type) return false;  // a typedef: its majority is its own (matrix_majority.h)
    BasicType b = describeBasicType(g.type);
    return b.ok && b.isMatrix && (b.rows == 1 || b.columns == 1);
}

}  // namespace fxport::xlate
