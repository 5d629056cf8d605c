// See static_object_aliases.h.
#include "rewrite/static_object_aliases.h"

#include <string>

#include "hlsl/aggregate_components.h"

namespace fxport::xlate {

namespace {

struct StaticObject {
    std::string name;
    size_t first = 0, semicolon = 0;  // the declaration's tokens
    std::string initial;              // the object of `= other`, if any
};

// `static [const] Type name [= other];` at file scope from i (after ';' or '}' at depth 0).
bool staticObjectAt(const std::vector<Token>& t, size_t i, StaticObject& out) {
    size_t j = i;
    if (!t[j].is("static")) return false;
    ++j;
    if (t[j].is("const")) ++j;
    if (!t[j].isIdent() || !isResourceType(t[j].text) || !t[j + 1].isIdent()) return false;
    out.name = t[j + 1].text;
    out.first = i;
    j += 2;
    if (t[j].is("=") && t[j + 1].isIdent() && t[j + 2].is(";")) {
        out.initial = t[j + 1].text;
        j += 2;
    }
    if (!t[j].is(";")) return false;
    out.semicolon = j;
    return true;
}

bool isGlobalObject(const EffectSyntax& syntax, const std::string& name) {
    return syntax.findTexture(name) != nullptr || syntax.findSampler(name) != nullptr;
}

}  // namespace

std::vector<TextEdit> staticObjectAliases(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    int depth = 0;
    for (size_t i = 0; i + 3 < t.size() && t[i].kind != Token::Kind::End; ++i) {
        if (t[i].is("{")) ++depth;
        if (t[i].is("}")) --depth;
        StaticObject s;
        if (depth != 0 || (i > 0 && !t[i - 1].is(";") && !t[i - 1].is("}")) || !staticObjectAt(t, i, s)) continue;
        // Every other mention: an assignment `name = other;` at a statement's start, or a use.
        std::string target = s.initial;
        std::vector<size_t> assignments, uses;
        bool ok = true;
        for (const auto& f : syntax.functions) {
            for (size_t k = f.body.begin; k < f.body.end && ok; ++k) {
                if (!t[k].is(s.name) || t[k - 1].is(".")) continue;
                const bool statement = t[k - 1].is(";") || t[k - 1].is("{") || t[k - 1].is("}");
                if (statement && t[k + 1].is("=") && t[k + 2].isIdent() && t[k + 3].is(";")) {
                    ok = target.empty() || target == t[k + 2].text;
                    target = t[k + 2].text;
                    assignments.push_back(k);
                    k += 3;
                } else if (t[k + 1].is("=") || t[k + 1].is("[")) {
                    ok = false;  // written some other way
                } else {
                    uses.push_back(k);
                }
            }
        }
        if (!ok || target.empty() || target == s.name || !isGlobalObject(syntax, target)) continue;
        edits.push_back({t[s.first].offset, t[s.semicolon].end, {}});
        for (size_t k : assignments) edits.push_back({t[k].offset, t[k + 3].end, {}});
        for (size_t k : uses) edits.push_back({t[k].offset, t[k].end, target});
        i = s.semicolon;
    }
    return edits;
}

}  // namespace fxport::xlate
