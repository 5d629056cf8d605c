// See static_initializer_calls.h.
#include "rewrite/static_initializer_calls.h"

#include <set>
#include <string>

namespace fxport::xlate {

namespace {

bool callsEffectFunction(const EffectSyntax& syntax, const FxGlobal& g) {
    const auto& t = syntax.tokens;
    for (size_t i = g.initializer.begin; i + 1 < g.initializer.end; ++i)
        if (t[i].isIdent() && t[i + 1].is("(") && (i == 0 || !t[i - 1].is(".")) && syntax.findFunction(t[i].text)) return true;
    return false;
}

// The first token of the declaration that declares `g` (its modifiers and type; `static float a =
// f(), b = f();` is one declaration).
size_t declarationStart(const EffectSyntax& syntax, const FxGlobal& g) {
    const auto& t = syntax.tokens;
    size_t k = g.token;
    while (k > 0 && !t[k - 1].is(";") && !t[k - 1].is("}")) --k;
    return k;
}

}  // namespace

bool hasInitializerCalls(const EffectSyntax& syntax) {
    for (const FxGlobal& g : syntax.globals)
        if (callsEffectFunction(syntax, g)) return true;
    return false;
}

std::vector<TextEdit> initializerCallScopes(const EffectSyntax& syntax) {
    std::set<size_t> starts;
    for (const FxGlobal& g : syntax.globals)
        if (callsEffectFunction(syntax, g)) starts.insert(declarationStart(syntax, g));
    // A chain: each function calls the one before it; the last is the one the wrapper calls.
    std::vector<TextEdit> edits;
    std::string previous;
    for (size_t start : starts) {
        const bool last = start == *starts.rbegin();
        const std::string name = std::string(kStaticInitializerScopes) + (last ? "" : "_" + std::to_string(edits.size()));
        edits.push_back({syntax.tokens[start].offset, syntax.tokens[start].offset,
                         "void " + name + "() {" + (previous.empty() ? "" : " " + previous + "();") + " } "});
        previous = name;
    }
    // Geometry, hull, domain and compute entries run without the entry wrapper: each function
    // defined after the chain calls its last link first too (the links are empty: calling them
    // from a function that is no entry changes nothing).
    const auto& t = syntax.tokens;
    for (const FxFunction& f : syntax.functions) {
        if (starts.empty() || f.declaration.begin < *starts.rbegin() || f.body.begin == 0 || !t[f.body.begin - 1].is("{")) continue;
        edits.push_back({t[f.body.begin].offset, t[f.body.begin].offset, std::string(kStaticInitializerScopes) + "(); "});
    }
    return edits;
}

}  // namespace fxport::xlate
