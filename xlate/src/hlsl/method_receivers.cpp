// See method_receivers.h. Read backwards from the '.' to the variable, then forwards from its
// declaration through each subscript and member.
#include "hlsl/method_receivers.h"

#include <cstdlib>
#include <vector>

#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

struct Declared {
    std::string type;
    std::vector<int> dims;
};

// One step after the variable: `[...]` (an element) or `.name` (a member).
struct Step {
    bool element = false;
    std::string member;
};

bool isObjectType(const std::string& type) {
    for (const char* prefix : {"Texture", "RWTexture", "RasterizerOrdered", "Buffer", "RWBuffer", "StructuredBuffer", "RWStructuredBuffer",
                               "AppendStructuredBuffer", "ConsumeStructuredBuffer", "ByteAddressBuffer", "RWByteAddressBuffer"})
        if (type.rfind(prefix, 0) == 0) return true;
    return false;
}

// `[4][2]` after token `i`, literal sizes only.
std::optional<std::vector<int>> literalDims(const std::vector<Token>& t, size_t i, size_t end) {
    std::vector<int> dims;
    for (; i + 2 < end && t[i].is("["); i += 3) {
        if (t[i + 1].kind != Token::Kind::Number || !t[i + 2].is("]")) return std::nullopt;
        dims.push_back(std::atoi(t[i + 1].text.c_str()));
    }
    return dims;
}

// The nearest `TYPE name` before `at` in f's body whose TYPE is an object, a struct or a number
// (`Texture2D<float4> t = T;`, `Texture2D t;`); `return name;` and the like are no declarations.
std::optional<Declared> localDeclaration(const EffectSyntax& syntax, const FxFunction& f, const std::string& name, size_t at) {
    const auto& t = syntax.tokens;
    for (size_t k = at; k > f.body.begin + 1;) {
        --k;
        if (!t[k].isIdent() || t[k].text != name || k + 1 >= f.body.end) continue;
        const Token& after = t[k + 1];
        if (!(after.is(";") || after.is("=") || after.is("[") || after.is(",") || after.is(":"))) continue;
        size_t typeToken = k - 1;
        std::string type = t[typeToken].text;
        if (t[typeToken].is(">")) {  // a template: Texture2D<float4>
            size_t open = typeToken;
            while (open > f.body.begin && !t[open].is("<")) --open;
            if (open <= f.body.begin || !t[open - 1].isIdent()) continue;
            type = t[open - 1].text + syntax.text({open, typeToken + 1});
        } else if (!t[typeToken].isIdent()) {
            continue;
        }
        const std::string& resolved = syntax.resolveType(type);
        if (!isObjectType(resolved) && !syntax.findStruct(resolved) && !describeBasicType(resolved).ok) continue;
        auto dims = literalDims(t, k + 1, f.body.end);
        if (!dims) return std::nullopt;
        return Declared{type, *dims};
    }
    return std::nullopt;
}

std::optional<Declared> declaration(const EffectSyntax& syntax, const FxFunction& f, const std::string& name, size_t at) {
    if (auto local = localDeclaration(syntax, f, name, at)) return local;
    for (const auto& p : f.parameters)
        if (p.name == name) return Declared{p.type, p.arrayDims};
    if (const FxTexture* texture = syntax.findTexture(name)) return Declared{texture->type, texture->arrayDims};
    for (const auto& g : syntax.globals)
        if (g.name == name) return Declared{g.type, g.arrayDims};
    return std::nullopt;
}

}  // namespace

std::optional<MethodReceiver> methodReceiver(const EffectSyntax& syntax, const FxFunction& f, size_t dot) {
    const auto& t = syntax.tokens;
    std::vector<Step> steps;  // last first
    size_t i = dot;
    while (true) {
        if (i <= f.body.begin) return std::nullopt;
        if (t[i - 1].is("]")) {
            int depth = 0;
            size_t j = i - 1;
            for (; j > f.body.begin; --j) {
                if (t[j].is("]")) ++depth;
                if (t[j].is("[") && --depth == 0) break;
            }
            if (depth != 0) return std::nullopt;
            steps.push_back({true, {}});
            i = j;
            continue;
        }
        if (!t[i - 1].isIdent()) return std::nullopt;
        if (i >= f.body.begin + 2 && t[i - 2].is(".")) {
            steps.push_back({false, t[i - 1].text});
            i -= 2;
            continue;
        }
        break;
    }
    const size_t begin = i - 1;
    auto declared = declaration(syntax, f, t[begin].text, begin);
    if (!declared) return std::nullopt;
    std::string type = syntax.resolveType(declared->type);
    std::vector<int> dims = declared->dims;
    for (auto s = steps.rbegin(); s != steps.rend(); ++s) {
        if (s->element) {
            if (dims.empty()) return std::nullopt;  // a texture's own subscript reads a texel
            dims.erase(dims.begin());
            continue;
        }
        const FxStruct* st = dims.empty() ? syntax.findStruct(type) : nullptr;
        if (!st) return std::nullopt;
        const FxStructMember* member = nullptr;
        for (const auto& m : st->members)
            if (m.name == s->member) member = &m;
        if (!member) return std::nullopt;
        type = syntax.resolveType(member->type);
        dims = member->arrayDims;
    }
    if (!dims.empty()) return std::nullopt;
    return MethodReceiver{begin, type};
}

}  // namespace fxport::xlate
