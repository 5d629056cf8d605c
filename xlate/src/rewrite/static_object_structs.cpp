// See static_object_structs.h.
#include "rewrite/static_object_structs.h"

#include <string>

#include "hlsl/aggregate_components.h"

namespace fxport::xlate {

namespace {

struct StaticStruct {
    const FxStruct* type = nullptr;
    std::string name;
    size_t first = 0, semicolon = 0;   // the declaration's tokens
    std::vector<std::string> objects;  // the initializer's elements, one per member
};

bool isGlobalObject(const EffectSyntax& syntax, const std::string& name) {
    return syntax.findTexture(name) != nullptr || syntax.findSampler(name) != nullptr;
}

// `static [const] S name = { a, b, ... };` at file scope from i, S a struct of objects only.
bool staticStructAt(const EffectSyntax& syntax, size_t i, StaticStruct& out) {
    const auto& t = syntax.tokens;
    size_t j = i;
    if (!t[j].is("static")) return false;
    ++j;
    if (t[j].is("const")) ++j;
    if (!t[j].isIdent() || !t[j + 1].isIdent() || !t[j + 2].is("=") || !t[j + 3].is("{")) return false;
    out.type = syntax.findStruct(t[j].text);
    if (!out.type || out.type->members.empty()) return false;
    for (const auto& m : out.type->members)
        if (!isResourceType(m.type) || !m.arrayDims.empty()) return false;
    out.name = t[j + 1].text;
    out.first = i;
    for (j += 4;; j += 2) {
        if (!t[j].isIdent() || !isGlobalObject(syntax, t[j].text)) return false;
        out.objects.push_back(t[j].text);
        if (t[j + 1].is("}")) break;
        if (!t[j + 1].is(",")) return false;
    }
    if (out.objects.size() != out.type->members.size() || !t[j + 2].is(";")) return false;
    out.semicolon = j + 2;
    return true;
}

// A parameter or local of the function named `name` (OGRE's Instancing_ps.cg: `float
// calcDepthShadow(sampler2D shadowMap, ...)` beside the global `shadowMap`): its uses are not the global's.
bool declaresOwn(const EffectSyntax& syntax, const FxFunction& f, const std::string& name) {
    for (const auto& p : f.parameters)
        if (p.name == name) return true;
    const auto& t = syntax.tokens;
    for (size_t k = f.body.begin + 1; k < f.body.end; ++k)
        if (t[k].is(name) && t[k - 1].isIdent() && !t[k - 1].is("return")) return true;
    return false;
}

std::string builder(const StaticStruct& s) {
    const std::string f = "fxport_static_" + s.name;
    std::string r = s.type->name + " " + f + "() { " + s.type->name + " r; ";
    for (size_t m = 0; m < s.objects.size(); ++m) r += "r." + s.type->members[m].name + " = " + s.objects[m] + "; ";
    return r + "return r; }";
}

}  // namespace

std::vector<TextEdit> staticObjectStructs(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    int depth = 0;
    for (size_t i = 0; i + 5 < t.size() && t[i].kind != Token::Kind::End; ++i) {
        if (t[i].is("{")) ++depth;
        if (t[i].is("}")) --depth;
        StaticStruct s;
        if (depth != 0 || (i > 0 && !t[i - 1].is(";") && !t[i - 1].is("}")) || !staticStructAt(syntax, i, s)) continue;
        std::vector<TextEdit> uses;
        bool written = false;
        for (const auto& f : syntax.functions) {
            if (f.body.begin < s.semicolon || declaresOwn(syntax, f, s.name)) continue;  // another `name` there
            for (size_t k = f.body.begin; k < f.body.end && !written; ++k) {
                if (!t[k].is(s.name) || t[k - 1].is(".")) continue;
                if (t[k + 1].is(".") && t[k + 2].isIdent()) {
                    size_t m = 0;
                    while (m < s.objects.size() && s.type->members[m].name != t[k + 2].text) ++m;
                    if (m == s.objects.size()) continue;  // not a member: left to glslang
                    written = t[k + 3].is("=");
                    uses.push_back({t[k].offset, t[k + 2].end, s.objects[m]});
                    continue;
                }
                written = t[k + 1].is("=") || t[k + 1].is("[");
                uses.push_back({t[k].offset, t[k].end, "fxport_static_" + s.name + "()"});
            }
        }
        if (written) continue;
        edits.push_back({t[s.first].offset, t[s.semicolon].end, builder(s)});
        edits.insert(edits.end(), uses.begin(), uses.end());
        i = s.semicolon;
    }
    return edits;
}

}  // namespace fxport::xlate
