// Implicit argument conversions fxc performs with warning X3206 (see implicit_conversions.h).
#include "checks/implicit_conversions.h"

#include <map>
#include <optional>

#include "hlsl/hlsl_types.h"
#include "fx/source_map.h"
#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

bool isOutParameter(const FxParameter& p) {
    for (const auto& m : p.modifiers)
        if (m == "out" || m == "inout") return true;
    return false;
}

// The numeric vector/scalar type of a parameter, or nothing (structs, matrices, arrays, objects).
std::optional<BasicType> vectorOrScalar(const EffectSyntax& syntax, const std::string& type) {
    BasicType b = describeBasicType(syntax.resolveType(type));
    if (!b.ok || b.isMatrix) return std::nullopt;
    return b;
}

// Type of a chain `name(.member)*(.swizzle)?` inside function `f` before token `at`: what its
// declaration says (parameter, nearest earlier local, global), through struct members, then a
// swizzle's length. Nothing when anything is not evident.
std::optional<BasicType> typeOfArgument(const EffectSyntax& syntax, const FxFunction& f, TokenSpan arg) {
    const auto& t = syntax.tokens;
    if (arg.empty() || !t[arg.begin].isIdent()) return std::nullopt;
    // A constructor: float3(...)
    if (arg.end > arg.begin + 1 && t[arg.begin + 1].is("(") && t[arg.end - 1].is(")")) {
        int depth = 0;
        for (size_t i = arg.begin + 1; i < arg.end; ++i) {
            if (t[i].is("(")) ++depth;
            else if (t[i].is(")") && --depth == 0 && i + 1 != arg.end) return std::nullopt;
        }
        if (auto b = vectorOrScalar(syntax, t[arg.begin].text); b && t[arg.begin].text != b->scalar) return b;
        return std::nullopt;
    }
    for (size_t i = arg.begin + 1; i < arg.end; i += 2)
        if (!t[i].is(".") || i + 1 >= arg.end || !t[i + 1].isIdent()) return std::nullopt;
    const std::string& name = t[arg.begin].text;
    std::string type;
    for (size_t i = arg.begin; i-- > f.body.begin;) {  // nearest earlier `Type name` in the body
        if (t[i + 1].text == name && t[i].isIdent() && (i + 2 >= t.size() || !t[i + 2].is("("))) {
            if (describeBasicType(syntax.resolveType(t[i].text)).ok || syntax.findStruct(syntax.resolveType(t[i].text))) {
                type = t[i].text;
                break;
            }
        }
    }
    if (type.empty())
        for (const auto& p : f.parameters)
            if (p.name == name && p.arrayDims.empty()) type = p.type;
    if (type.empty())
        for (const auto& g : syntax.globals)
            if (g.name == name && g.arrayDims.empty()) type = g.type;
    if (type.empty()) return std::nullopt;
    for (size_t i = arg.begin + 2; i < arg.end; i += 2) {
        const std::string& member = t[i].text;
        if (const FxStruct* s = syntax.findStruct(syntax.resolveType(type))) {
            std::string next;
            for (const auto& m : s->members)
                if (m.name == member && m.arrayDims.empty()) next = m.type;
            if (next.empty()) return std::nullopt;
            type = next;
            continue;
        }
        auto b = vectorOrScalar(syntax, type);
        if (!b || i + 1 != arg.end || member.size() > 4) return std::nullopt;
        bool xyzw = member.find_first_not_of("xyzw") == std::string::npos, rgba = member.find_first_not_of("rgba") == std::string::npos;
        if (!xyzw && !rgba) return std::nullopt;
        b->columns = static_cast<int>(member.size());
        return b;
    }
    return vectorOrScalar(syntax, type);
}

const char* typeName(const BasicType& b, std::string& buffer) {
    buffer = b.scalar + (b.columns > 1 ? std::to_string(b.columns) : std::string());
    return buffer.c_str();
}

}  // namespace

namespace {

// `T name = value;` in a body, T a vector or scalar and value wider (`float2 uv = input.TexCoord4;`):
// fxc warns X3206 and uses the first components, as glslang does silently.
void findTruncatingInitializations(const EffectSyntax& syntax, const SourceMap& map, const FxFunction& f, std::vector<Diagnostic>& out) {
    const auto& t = syntax.tokens;
    for (size_t i = f.body.begin; i + 3 < f.body.end; ++i) {
        if (!t[i].isIdent() || !t[i + 1].isIdent() || !t[i + 2].is("=") || (i > f.body.begin && t[i - 1].is("."))) continue;
        auto want = vectorOrScalar(syntax, t[i].text);
        if (!want) continue;
        size_t end = i + 3;
        for (int depth = 0; end < f.body.end; ++end) {
            if (t[end].is("(") || t[end].is("[") || t[end].is("{")) ++depth;
            else if (t[end].is(")") || t[end].is("]") || t[end].is("}")) --depth;
            else if (depth == 0 && (t[end].is(";") || t[end].is(","))) break;
        }
        if (end == i + 3 || end >= f.body.end) continue;
        auto have = typeOfArgument(syntax, f, {i + 3, end});
        if (!have || have->columns <= want->columns) continue;
        std::string h, w;
        out.push_back(map.make(Severity::Warning, diag::kImplicitConversion,
                               std::string(kTruncationWarning) + ": '" + t[i + 1].text + "' is " + typeName(*want, w) + ", initialised from " +
                                   typeName(*have, h) + (want->columns == 1 ? "; its first component is used" : "; its first components are used"),
                               t[i + 1].line, t[i + 1].column, t[i + 1].text));
    }
}

}  // namespace

std::vector<Diagnostic> findImplicitTruncations(const EffectSyntax& syntax, const SourceMap& map) {
    std::vector<Diagnostic> out;
    for (const auto& f : syntax.functions) findTruncatingInitializations(syntax, map, f, out);
    const auto& t = syntax.tokens;
    std::map<std::string, int> overloads;
    for (const auto& f : syntax.functions) ++overloads[f.name];
    for (const auto& f : syntax.functions) {
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
            if (!t[i].isIdent() || !t[i + 1].is("(") || overloads[t[i].text] != 1) continue;
            if (i > f.body.begin && t[i - 1].is(".")) continue;  // a method, not a call
            const FxFunction* callee = syntax.findFunction(t[i].text);
            if (!callee) continue;
            // Arguments at depth 1.
            std::vector<TokenSpan> args;
            int depth = 0;
            size_t start = i + 2;
            for (size_t j = i + 1; j < f.body.end; ++j) {
                if (t[j].is("(") || t[j].is("[") || t[j].is("{")) ++depth;
                else if (t[j].is(")") || t[j].is("]") || t[j].is("}")) {
                    if (--depth == 0) {
                        if (j > start) args.push_back({start, j});
                        break;
                    }
                } else if (depth == 1 && t[j].is(",")) {
                    args.push_back({start, j});
                    start = j + 1;
                }
            }
            if (args.size() > callee->parameters.size()) continue;
            for (size_t a = 0; a < args.size(); ++a) {
                const FxParameter& p = callee->parameters[a];
                if (!p.arrayDims.empty() || isOutParameter(p)) continue;
                auto want = vectorOrScalar(syntax, p.type);
                auto have = typeOfArgument(syntax, f, args[a]);
                if (!want || !have || have->columns <= want->columns) continue;
                std::string h, w;
                const Token& at = t[i];  // the call: `name(` is found in the original line
                out.push_back(map.make(Severity::Warning, diag::kImplicitConversion,
                                       std::string(kTruncationWarning) + ": argument " + std::to_string(a + 1) + " of '" + callee->name + "' is " +
                                           typeName(*have, h) + ", parameter '" + p.name + "' is " + typeName(*want, w) +
                                           (want->columns == 1 ? "; its first component is used" : "; its first components are used"),
                                       at.line, at.column, at.text + "("));
            }
        }
    }
    return out;
}

std::vector<TextEdit> vectorToScalarOverloads(const EffectSyntax& syntax, const std::set<std::string>& functions) {
    std::vector<TextEdit> edits;
    for (const auto& f : syntax.functions) {
        if (!functions.count(f.name) || f.declaration.empty()) continue;
        std::vector<size_t> scalars;
        for (size_t i = 0; i < f.parameters.size(); ++i) {
            const FxParameter& p = f.parameters[i];
            auto b = vectorOrScalar(syntax, p.type);
            if (b && b->columns == 1 && p.arrayDims.empty() && !isOutParameter(p)) scalars.push_back(i);
        }
        if (scalars.empty()) continue;
        // Width choices per scalar parameter: every combination for up to three of them, else one
        // parameter widened at a time (the overload count stays small).
        std::vector<std::vector<int>> variants;
        if (scalars.size() <= 3) {
            size_t count = 1;
            for (size_t k = 0; k < scalars.size(); ++k) count *= 4;
            for (size_t v = 1; v < count; ++v) {
                std::vector<int> widths;
                for (size_t k = 0, x = v; k < scalars.size(); ++k, x /= 4) widths.push_back(static_cast<int>(x % 4) + 1);
                variants.push_back(widths);
            }
        } else {
            for (size_t k = 0; k < scalars.size(); ++k)
                for (int w = 2; w <= 4; ++w) {
                    std::vector<int> widths(scalars.size(), 1);
                    widths[k] = w;
                    variants.push_back(widths);
                }
        }
        std::string text;
        for (const auto& widths : variants) {
            std::string params, args;
            for (size_t i = 0; i < f.parameters.size(); ++i) {
                const FxParameter& p = f.parameters[i];
                int width = 1;
                for (size_t k = 0; k < scalars.size(); ++k)
                    if (scalars[k] == i) width = widths[k];
                std::string type = p.type;
                if (width > 1) type = describeBasicType(syntax.resolveType(p.type)).scalar + std::to_string(width);
                for (const auto& m : p.modifiers)
                    if (m == "uniform" || m == "in" || m == "const") params += m + " ";
                params += type + " " + p.name;
                for (int d : p.arrayDims) params += "[" + std::to_string(d) + "]";
                if (i + 1 < f.parameters.size()) params += ", ";
                args += (i ? ", " : "") + p.name + (width > 1 ? ".x" : "");
            }
            // An overload the effect declares itself stays the effect's.
            bool exists = false;
            for (const auto& g : syntax.functions) {
                if (g.name != f.name || g.parameters.size() != f.parameters.size()) continue;
                bool same = true;
                for (size_t i = 0; i < g.parameters.size() && same; ++i) {
                    int width = 1;
                    for (size_t k = 0; k < scalars.size(); ++k)
                        if (scalars[k] == i) width = widths[k];
                    auto gb = vectorOrScalar(syntax, g.parameters[i].type);
                    auto fb = vectorOrScalar(syntax, f.parameters[i].type);
                    same = gb && fb ? gb->columns == (width > 1 ? width : fb->columns) && gb->scalar == fb->scalar
                                    : g.parameters[i].type == f.parameters[i].type;
                }
                exists |= same;
            }
            if (exists) continue;
            text += " " + f.returnType + " " + f.name + "(" + params + ") { " + (f.returnType == "void" ? "" : "return ") + f.name + "(" + args + "); }";
        }
        const Token& last = syntax.tokens[f.declaration.end - 1];
        edits.push_back({last.end, last.end, text});
    }
    return edits;
}

}  // namespace fxport::xlate
