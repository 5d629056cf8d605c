// See out_argument_casts.h: out/inout arguments through conversions, written back as fxc does.
#include "rewrite/out_argument_casts.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>

#include "hlsl/call_arguments.h"
#include "hlsl/expression_types.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

int components(const BasicType& b) { return b.rows * b.columns; }

bool hasModifier(const FxParameter& p, const char* m) {
    return std::find(p.modifiers.begin(), p.modifiers.end(), m) != p.modifiers.end();
}

std::optional<BasicType> vectorType(const EffectSyntax& syntax, const std::string& type) {
    BasicType b = describeBasicType(syntax.resolveType(type));
    if (!b.ok || b.isMatrix) return std::nullopt;
    return b;
}

const FxFunction* onlyOverload(const EffectSyntax& syntax, const std::string& name, size_t arity) {
    const FxFunction* found = nullptr;
    for (const auto& f : syntax.functions)
        if (f.name == name && f.parameters.size() == arity) {
            if (found) return nullptr;
            found = &f;
        }
    return found;
}

// One out/inout argument that needs the wrapper: `(casts) target` or a target of another type.
struct Conversion {
    size_t argument = 0;       // parameter index
    size_t argBegin = 0;       // first token of the argument (the first cast's '(')
    size_t targetBegin = 0;    // first token of the target
    std::string castText;      // the casts as written, outermost first
    std::optional<BasicType> outerCast;
    BasicType target, parameter;
    std::string uavElement;    // `u[i]` of a typed UAV passed inout: its text, passed once more as `in`
};

bool isTypedUavType(std::string type) {
    type.erase(std::remove_if(type.begin(), type.end(), [](unsigned char c) { return std::isspace(c); }), type.end());
    return type.rfind("RWBuffer<", 0) == 0 || type.rfind("RWTexture", 0) == 0;
}

// `u[...]` or `u[...].xy` filling [begin, end), u a global typed UAV, the index free of writes and
// calls of user functions (it is evaluated twice): its text on one line, else empty.
std::string uavElementText(const EffectSyntax& syntax, size_t begin, size_t end) {
    const auto& t = syntax.tokens;
    if (end < begin + 3 || !t[begin].isIdent() || !t[begin + 1].is("[")) return "";
    auto g = std::find_if(syntax.globals.begin(), syntax.globals.end(), [&](const FxGlobal& x) { return x.name == t[begin].text; });
    if (g == syntax.globals.end() || !isTypedUavType(g->type)) return "";
    int depth = 0;
    size_t close = begin + 1;
    for (; close < end; ++close) {
        if (t[close].is("[") || t[close].is("(")) ++depth;
        if ((t[close].is("]") || t[close].is(")")) && --depth == 0) break;
        for (const char* op : {"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>=", "++", "--"})
            if (t[close].is(op)) return "";
        if (t[close].isIdent() && close + 1 < end && t[close + 1].is("("))
            for (const auto& f : syntax.functions)
                if (f.name == t[close].text) return "";
    }
    if (close >= end || !(close + 1 == end || (close + 3 == end && t[close + 1].is(".") && t[close + 2].isIdent()))) return "";
    std::string text;
    for (size_t k = begin; k < end; ++k) text += (k > begin ? " " : "") + t[k].text;
    return text;
}

std::optional<Conversion> conversionOf(const EffectSyntax& syntax, const FxFunction& caller, const FxParameter& p,
                                       size_t begin, size_t end) {
    const auto& t = syntax.tokens;
    const bool inout = hasModifier(p, "inout");
    if (!inout && !hasModifier(p, "out")) return std::nullopt;
    Conversion c;
    c.argBegin = begin;
    if (inout && p.arrayDims.empty()) {
        c.uavElement = uavElementText(syntax, begin, end);
        if (!c.uavElement.empty()) {
            c.targetBegin = begin;
            return c;
        }
    }
    size_t at = begin;
    while (at + 3 < end && t[at].is("(") && t[at + 1].isIdent() && t[at + 2].is(")")) {
        auto cast = vectorType(syntax, t[at + 1].text);
        if (!cast) return std::nullopt;
        if (!c.outerCast) c.outerCast = cast;
        c.castText += "(" + t[at + 1].text + ")";
        at += 3;
    }
    c.targetBegin = at;
    if (!t[at].isIdent()) return std::nullopt;
    for (size_t k = at + 1; k < end; k += 2)
        if (!t[k].is(".") || k + 1 >= end || !t[k + 1].isIdent()) return std::nullopt;
    auto targetType = expressionType(syntax, caller, at, end);
    auto parameter = vectorType(syntax, p.type);
    if (!targetType || !targetType->isNumeric() || targetType->basic.isMatrix || targetType->keptMatrix || !parameter ||
        !p.arrayDims.empty())
        return std::nullopt;
    c.target = targetType->basic;
    c.parameter = *parameter;
    if (c.outerCast) {
        // A cast of another size than the parameter (`f((float2)p)` for an out float4) fxc refuses,
        // and so does glslang.
        if (components(*c.outerCast) > components(c.target) || components(*c.outerCast) != components(c.parameter))
            return std::nullopt;
        return c;
    }
    // No cast: glslang writes an out argument back itself; an inout one of another type it does not.
    if (!inout || spellType(c.target) == spellType(c.parameter) || components(c.target) != components(c.parameter))
        return std::nullopt;
    return c;
}

// The wrapper: `R name(params) { P t = ...; R r = callee(...); target = ...; return r; }`, on one
// line (edits keep the line count).
std::string wrapper(const FxFunction& callee, const std::string& name, const std::vector<Conversion>& conversions) {
    std::string params, args, before, after;
    for (size_t k = 0; k < callee.parameters.size(); ++k) {
        const FxParameter& p = callee.parameters[k];
        const std::string a = "fxport_a" + std::to_string(k);
        auto c = std::find_if(conversions.begin(), conversions.end(), [&](const Conversion& x) { return x.argument == k; });
        if (k) params += ", ", args += ", ";
        if (c == conversions.end()) {
            for (const auto& m : p.modifiers)
                if (m == "in" || m == "out" || m == "inout") params += m + " ";
            params += p.type + " " + a;
            for (int d : p.arrayDims) params += "[" + std::to_string(d) + "]";
            args += a;
            continue;
        }
        if (!c->uavElement.empty()) {  // read through the extra `in` copy, written back through the `out` one
            params += "in " + p.type + " " + a + "_in, out " + p.type + " " + a;
            before += a + " = " + a + "_in; ";
            args += a;
            continue;
        }
        const std::string tmp = "fxport_t" + std::to_string(k), param = spellType(c->parameter);
        params += "inout " + spellType(c->target) + " " + a;
        args += tmp;
        before += param + " " + tmp + (hasModifier(p, "inout") ? " = (" + param + ")(" + c->castText + a + ")" : "") + "; ";
        if (!c->outerCast) {
            after += a + " = (" + spellType(c->target) + ")" + tmp + "; ";
        } else if (components(*c->outerCast) < components(c->target)) {
            // The target's first components take the value, converted by the outermost cast.
            after += a + "." + std::string("xyzw").substr(0, size_t(components(*c->outerCast))) + " = (" +
                     spellType(*c->outerCast) + ")" + tmp + "; ";
        } else {
            after += a + " = (" + spellType(c->target) + ")(" + spellType(*c->outerCast) + ")" + tmp + "; ";
        }
    }
    const bool returns = callee.returnType != "void";
    std::string text = callee.returnType + " " + name + "(" + params + ") { " + before;
    text += (returns ? callee.returnType + " fxport_r = " : std::string()) + callee.name + "(" + args + "); " + after;
    return text + (returns ? "return fxport_r; } " : "} ");
}

}  // namespace

std::vector<TextEdit> outArgumentsThroughConversions(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    int made = 0;
    for (const auto& caller : syntax.functions) {
        if (caller.declaration.empty() || caller.body.empty()) continue;
        std::string wrappers;
        for (size_t i = caller.body.begin; i + 1 < caller.body.end; ++i) {
            if (!t[i].isIdent() || !t[i + 1].is("(") || t[i - 1].is(".")) continue;
            auto spans = callArgumentSpans(t, i + 1, caller.body.end);
            const FxFunction* callee = spans.empty() ? nullptr : onlyOverload(syntax, t[i].text, spans.size());
            if (!callee || callee == &caller) continue;
            std::vector<Conversion> conversions;
            for (size_t a = 0; a < spans.size(); ++a)
                if (auto c = conversionOf(syntax, caller, callee->parameters[a], spans[a].first, spans[a].second)) {
                    c->argument = a;
                    conversions.push_back(*c);
                }
            if (conversions.empty()) continue;
            const std::string name = "fxport_outarg" + std::to_string(made++) + "_" + callee->name;
            wrappers += wrapper(*callee, name, conversions);
            edits.push_back({t[i].offset, t[i].end, name});
            for (const auto& c : conversions) {
                if (c.targetBegin > c.argBegin) edits.push_back({t[c.argBegin].offset, t[c.targetBegin].offset, ""});
                if (!c.uavElement.empty()) edits.push_back({t[c.argBegin].offset, t[c.argBegin].offset, c.uavElement + ", "});
            }
        }
        if (!wrappers.empty()) {
            size_t at = t[caller.declaration.begin].offset;
            edits.push_back({at, at, wrappers});
        }
    }
    return edits;
}

}  // namespace fxport::xlate
