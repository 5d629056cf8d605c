// See numthreads_sizes.h.
#include "rewrite/numthreads_sizes.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <map>

#include "fx/constant_eval.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

// float, half, double, min16float, min10float.
bool isRealType(const std::string& scalar) { return scalar == "half" || scalar == "double" || scalar.find("float") != std::string::npos; }

// `1.5`, `2e3`, `1.0f`, `2h`: a float literal (hex `0x1F` is an integer).
bool isFloatLiteral(const std::string& s) {
    if (s.size() > 1 && (s[1] == 'x' || s[1] == 'X')) return false;
    return s.find_first_of(".eEfFhH") != std::string::npos;
}

// The scalar constants a size may name: statics and consts declared before token `before` (fxc
// takes a static's initial value), with whether each is of a real type.
struct Constants {
    std::map<std::string, std::vector<double>> values;
    std::map<std::string, bool> real;
};

Constants constantsBefore(const EffectSyntax& syntax, size_t before) {
    Constants c;
    auto has = [](const FxGlobal& g, const char* m) { return std::find(g.modifiers.begin(), g.modifiers.end(), m) != g.modifiers.end(); };
    for (const FxGlobal& g : syntax.globals) {
        if (g.token >= before || g.initializer.empty() || !g.arrayDims.empty() || !(has(g, "static") || has(g, "const"))) continue;
        BasicType b = describeBasicType(syntax.resolveType(g.type));
        if (!b.ok || b.rows * b.columns != 1) continue;
        auto v = evaluateConstant(syntax, g.initializer, c.values);
        if (!v || v->size() != 1) continue;
        c.real[g.name] = isRealType(b.scalar);
        c.values[g.name] = {c.real[g.name] ? (*v)[0] : std::trunc((*v)[0])};
    }
    return c;
}

// Why the argument at `span` is no integer, or "" when it may be one: a string, a float literal, a
// real type's constructor or a real constant in it.
std::string notAnInteger(const EffectSyntax& syntax, TokenSpan span, const Constants& c) {
    for (size_t k = span.begin; k < span.end; ++k) {
        const Token& t = syntax.tokens[k];
        if (t.kind == Token::Kind::String) return "a string";
        if (t.kind == Token::Kind::Number && isFloatLiteral(t.text)) return "'" + t.text + "' is a float literal";
        if (!t.isIdent()) continue;
        BasicType b = describeBasicType(syntax.resolveType(t.text));
        auto constant = c.real.find(t.text);
        if ((b.ok && isRealType(b.scalar)) || (constant != c.real.end() && constant->second)) return "'" + t.text + "' is a real type";
    }
    return {};
}

// The argument's text for a message, spaced as written (after macros): `x++`, `float(1)`.
std::string asWritten(const EffectSyntax& syntax, TokenSpan span) {
    std::string out;
    for (size_t k = span.begin; k < span.end; ++k) {
        const Token& t = syntax.tokens[k];
        if (k > span.begin && t.offset > syntax.tokens[k - 1].end) out += ' ';
        out += t.kind == Token::Kind::String ? '"' + t.text + '"' : t.text;
    }
    return out;
}

ThreadGroupSize evaluate(const EffectSyntax& syntax, TokenSpan span, const Constants& c) {
    ThreadGroupSize size{span, std::nullopt, {}};
    const std::string text = asWritten(syntax, span);
    if (std::string why = notAnInteger(syntax, span, c); !why.empty()) {
        size.problem = "'" + text + "' is not an integer (" + why + "): each thread-group dimension is an integer";
        return size;
    }
    auto lookup = [&c](const std::string& name, bool array) -> const std::vector<double>* {
        auto it = c.values.find(name);
        return array || it == c.values.end() ? nullptr : &it->second;
    };
    auto v = evaluateConstantWith(syntax, span, lookup, nullptr, true);
    if (!v || v->size() != 1 || !std::isfinite((*v)[0]) || std::fabs((*v)[0]) > double(INT_MAX))
        size.problem = "'" + text + "' is no integer constant fxport can evaluate";
    else if ((*v)[0] < 1)
        size.problem = "'" + text + "' is " + std::to_string(static_cast<long long>((*v)[0])) + "; each thread-group dimension must be at least 1";
    else
        size.value = static_cast<long long>((*v)[0]);
    return size;
}

}  // namespace

std::vector<ThreadGroupSize> threadGroupSizes(const EffectSyntax& syntax, const FxFunction& f) {
    const auto& t = syntax.tokens;
    std::vector<ThreadGroupSize> sizes;
    for (size_t i = f.attributeTokens.begin; i + 2 < f.attributeTokens.end; ++i) {
        if (!t[i].is("[") || !t[i + 1].is("numthreads") || !t[i + 2].is("(")) continue;
        const Constants constants = constantsBefore(syntax, i);
        int depth = 0;
        size_t start = i + 3;
        for (size_t k = i + 2; k < f.attributeTokens.end; ++k) {
            if (t[k].is("(") || t[k].is("[") || t[k].is("{")) ++depth;
            if (t[k].is(")") || t[k].is("]") || t[k].is("}")) --depth;
            if ((depth == 1 && t[k].is(",")) || depth == 0) {
                sizes.push_back(evaluate(syntax, {start, k}, constants));
                start = k + 1;
            }
            if (depth == 0) break;
        }
        break;
    }
    return sizes;
}

std::vector<TextEdit> threadGroupSizesAsLiterals(const EffectSyntax& syntax) {
    std::vector<TextEdit> edits;
    for (const FxFunction& f : syntax.functions) {
        const std::vector<ThreadGroupSize> sizes = threadGroupSizes(syntax, f);
        if (sizes.size() != 3 || std::any_of(sizes.begin(), sizes.end(), [](const ThreadGroupSize& s) { return !s.value; })) continue;
        for (const ThreadGroupSize& s : sizes)
            if (s.span.end != s.span.begin + 1 || syntax.tokens[s.span.begin].text != std::to_string(*s.value))
                edits.push_back({syntax.tokens[s.span.begin].offset, syntax.tokens[s.span.end - 1].end, std::to_string(*s.value)});
    }
    return edits;
}

}  // namespace fxport::xlate
