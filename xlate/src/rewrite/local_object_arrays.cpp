// See local_object_arrays.h.
#include "rewrite/local_object_arrays.h"

#include <cstdlib>
#include <string>

#include "hlsl/aggregate_components.h"

namespace fxport::xlate {

namespace {

bool isGlobalObject(const EffectSyntax& syntax, const std::string& name) {
    return syntax.findTexture(name) != nullptr || syntax.findSampler(name) != nullptr;
}

// `T name[N] = { a, b, ... };` at i (T an object type, each element a global object): the element
// names and the index of the `;`, or nothing.
bool declarationAt(const EffectSyntax& syntax, size_t i, size_t end, std::vector<std::string>& elements, size_t& semicolon) {
    const auto& t = syntax.tokens;
    if (i + 7 >= end || !t[i].isIdent() || !isResourceType(t[i].text) || !t[i + 1].isIdent() || !t[i + 2].is("[") ||
        t[i + 3].kind != Token::Kind::Number || !t[i + 4].is("]") || !t[i + 5].is("=") || !t[i + 6].is("{"))
        return false;
    const long n = std::strtol(t[i + 3].text.c_str(), nullptr, 10);
    size_t j = i + 7;
    for (; j + 1 < end; j += 2) {
        if (!t[j].isIdent() || !isGlobalObject(syntax, t[j].text)) return false;
        elements.push_back(t[j].text);
        if (t[j + 1].is("}")) break;
        if (!t[j + 1].is(",")) return false;
    }
    if (long(elements.size()) != n || j + 2 >= end || !t[j + 2].is(";")) return false;
    semicolon = j + 2;
    return true;
}

}  // namespace

std::vector<TextEdit> localObjectArraysResolved(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const FxFunction& f : syntax.functions) {
        if (f.body.empty()) continue;
        for (size_t i = f.body.begin; i < f.body.end; ++i) {
            std::vector<std::string> elements;
            size_t semicolon = 0;
            if (!(t[i - 1].is(";") || t[i - 1].is("{") || t[i - 1].is("}")) || !declarationAt(syntax, i, f.body.end, elements, semicolon)) continue;
            const std::string& name = t[i + 1].text;
            std::vector<TextEdit> uses;
            bool resolvable = true;
            for (size_t k = f.body.begin; k < f.body.end && resolvable; ++k) {
                if (k >= i && k <= semicolon) continue;
                if (!t[k].is(name) || t[k - 1].is(".")) continue;
                const bool element = t[k + 1].is("[") && t[k + 2].kind == Token::Kind::Number && t[k + 3].is("]") && !t[k + 4].is("=");
                const long index = element ? std::strtol(t[k + 2].text.c_str(), nullptr, 10) : -1;
                if (!element || index < 0 || index >= long(elements.size()) || t[k + 2].text.find_first_not_of("0123456789") != std::string::npos) {
                    resolvable = false;  // another use, or the name declared again: left to glslang
                    break;
                }
                uses.push_back({t[k].offset, t[k + 3].end, elements[size_t(index)]});
            }
            if (!resolvable) continue;
            edits.push_back({t[i].offset, t[semicolon].end, {}});
            edits.insert(edits.end(), uses.begin(), uses.end());
            i = semicolon;
        }
    }
    return edits;
}

}  // namespace fxport::xlate
