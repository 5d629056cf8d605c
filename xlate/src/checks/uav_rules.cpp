// fxc's rules for unordered-access views that glslang's HLSL front end does not check (vkd3d's
// uav-atomics and uav-rwtexture pin them):
//  - cs_4_x has raw and structured UAVs only: a RWBuffer or RWTexture* there is refused;
//  - the Interlocked* intrinsics return nothing (their old value comes back through an out
//    argument), so a call used as a value is an error;
//  - an interlocked operation on a typed UAV wants int or uint elements (not int1, float ...);
//  - a structured buffer's element holds no object (texture, sampler, buffer), directly or in a
//    struct member;
//  - a pixel shader's UAVs share slots with its render targets: register(uN) must lie above the
//    highest SV_Target the entry writes.
#include <algorithm>
#include <cctype>

#include "checks/fxc_checks.h"
#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

std::string withoutSpaces(std::string s) {
    s.erase(std::remove_if(s.begin(), s.end(), [](unsigned char c) { return std::isspace(c); }), s.end());
    return s;
}

bool isTypedUav(const std::string& type) {
    std::string t = withoutSpaces(type);
    return t.rfind("RWBuffer<", 0) == 0 || t.rfind("RWTexture", 0) == 0;
}

// T of `RWBuffer<T>` / `RWTexture2D<T>`.
std::string elementType(const std::string& type) {
    std::string t = withoutSpaces(type);
    size_t open = t.find('<'), close = t.rfind('>');
    return open == std::string::npos || close == std::string::npos || close < open ? std::string() : t.substr(open + 1, close - open - 1);
}

bool isStatementStart(const Token& t) {
    for (const char* s : {";", "{", "}", ")", "else", ":"})
        if (t.is(s)) return true;
    return false;
}

// The render-target index of a pixel-shader output semantic (SV_Target3 -> 3), -1 if none.
int targetIndex(const std::string& semantic) {
    std::string s = toLower(semantic);
    if (s.rfind("sv_target", 0) != 0) return -1;
    std::string digits = s.substr(9);
    if (digits.empty()) return 0;
    if (!std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c); }) || digits.size() > 2) return -1;
    return std::stoi(digits);
}

class UavRules : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& f : syntax_.functions) interlockedCalls(f);
        for (const auto& g : syntax_.globals) structuredElement(g);
        for (const auto& e : compiledEntries()) {
            if (e.profile.stage == ShaderStage::Compute && e.profile.major == 4) typedUavsInCs4(e);
            if (e.profile.stage == ShaderStage::Pixel) pixelUavSlots(e);
        }
    }

private:
    const FxGlobal* global(const std::string& name) const {
        for (const auto& g : syntax_.globals)
            if (g.name == name) return &g;
        return nullptr;
    }

    void interlockedCalls(const FxFunction& f) {
        for (size_t i = f.body.begin; i + 2 < f.body.end; ++i) {
            if (!t_[i].isIdent() || t_[i].text.rfind("Interlocked", 0) != 0 || !t_[i + 1].is("(") || (i > 0 && t_[i - 1].is("."))) continue;
            if (i > 0 && !isStatementStart(t_[i - 1]))
                report("'" + t_[i].text + "' returns nothing (void): its result cannot be used; the original value comes back in its last argument", i);
            const FxGlobal* g = tok(i + 2).isIdent() && tok(i + 3).is("[") ? global(t_[i + 2].text) : nullptr;
            if (!g || !isTypedUav(g->type)) continue;
            std::string element = syntax_.resolveType(elementType(g->type));
            if (element != "int" && element != "uint" && element != "dword")
                report("'" + t_[i].text + "' needs a scalar int or uint destination; '" + g->name + "' holds " + elementType(g->type), i + 2);
        }
    }

    static bool isObjectType(const std::string& t) {
        for (const char* prefix : {"Texture", "RWTexture", "sampler", "Sampler", "Buffer", "RWBuffer", "StructuredBuffer", "RWStructuredBuffer",
                                   "ByteAddressBuffer", "RWByteAddressBuffer", "texture"})
            if (t.rfind(prefix, 0) == 0) return true;
        return false;
    }

    bool holdsObject(const std::string& type, int depth = 0) const {
        std::string t = withoutSpaces(syntax_.resolveType(type));
        if (t.rfind("struct", 0) == 0 && !syntax_.findStruct(t)) t = t.substr(6);
        if (isObjectType(t)) return true;
        if (const FxStruct* s = syntax_.findStruct(t); s && depth < 8)
            for (const auto& m : s->members)
                if (holdsObject(m.type, depth + 1)) return true;
        return false;
    }

    void structuredElement(const FxGlobal& g) {
        std::string t = withoutSpaces(g.type);
        if (t.rfind("StructuredBuffer<", 0) != 0 && t.rfind("RWStructuredBuffer<", 0) != 0) return;
        if (holdsObject(elementType(t)))
            report("the elements of structured buffer '" + g.name + "' (" + elementType(t) + ") cannot hold objects (textures, samplers, buffers)", g.token);
    }

    void typedUavsInCs4(const CompiledEntry& e) {
        auto reachable = reachableFrom(*e.function);
        for (const auto& g : syntax_.globals)
            if (isTypedUav(g.type) && mentionedIn(reachable, g.name))
                report("typed UAV '" + g.name + "' (" + withoutSpaces(g.type) + ") needs cs_5_0: " + e.profile.name +
                           " has RWByteAddressBuffer and RWStructuredBuffer only",
                       g.token);
    }

    void pixelUavSlots(const CompiledEntry& e) {
        int highest = targetIndex(e.function->returnSemantic);
        if (const FxStruct* s = syntax_.findStruct(syntax_.resolveType(e.function->returnType)))
            for (const auto& m : s->members) highest = std::max(highest, targetIndex(m.semantic));
        for (const auto& p : e.function->parameters)
            if (std::find(p.modifiers.begin(), p.modifiers.end(), "out") != p.modifiers.end()) highest = std::max(highest, targetIndex(p.semantic));
        if (highest < 0) return;
        auto reachable = reachableFrom(*e.function);
        for (const auto& g : syntax_.globals)
            if (g.registerClass == 'u' && g.registerIndex >= 0 && g.registerIndex <= highest && mentionedIn(reachable, g.name))
                report("UAV '" + g.name + "' at register(u" + std::to_string(g.registerIndex) + ") overlaps render target SV_Target" +
                           std::to_string(highest) + " of '" + e.function->name + "': a pixel shader's UAV slots begin above its render targets",
                       g.token);
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findUavRuleErrors(const EffectSyntax& syntax, const SourceMap& map) {
    UavRules check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
