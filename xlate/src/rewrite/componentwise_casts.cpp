// See componentwise_casts.h.
#include "rewrite/componentwise_casts.h"

#include <cstdlib>
#include <optional>
#include <string>

#include "hlsl/aggregate_components.h"
#include "hlsl/hlsl_types.h"
#include "hlsl/variable_declarations.h"

namespace fxport::xlate {

namespace {

using Declared = DeclaredVariable;

// `( [struct] T [N]... )` at token i: the type and sizes, and the index of ')'.
std::optional<std::pair<Declared, size_t>> castAt(const EffectSyntax& syntax, size_t i, size_t end) {
    const auto& t = syntax.tokens;
    if (!t[i].is("(")) return std::nullopt;
    size_t j = i + 1;
    if (j < end && t[j].is("struct")) ++j;
    if (j >= end || !t[j].isIdent()) return std::nullopt;
    Declared d{t[j].text, {}};
    const std::string& resolved = syntax.resolveType(d.type);
    if (!describeBasicType(resolved).ok && !syntax.findStruct(resolved)) return std::nullopt;
    for (++j; j + 2 < end && t[j].is("[") && t[j + 2].is("]"); j += 3) {
        if (t[j + 1].kind != Token::Kind::Number) return std::nullopt;
        d.dims.push_back(std::atoi(t[j + 1].text.c_str()));
    }
    if (j >= end || !t[j].is(")")) return std::nullopt;
    return std::make_pair(d, j);
}

std::string vectorSpelling(const BasicType& b) {
    const int n = b.rows * b.columns;
    if (b.isMatrix && b.rows > 1 && b.columns > 1) return b.scalar + std::to_string(b.rows) + "x" + std::to_string(b.columns);
    return n > 1 ? b.scalar + std::to_string(n) : b.scalar;
}

// `T(x)`, T numeric and x an array or struct variable of exactly T's count: T from x's components.
void rewriteConstructor(const EffectSyntax& syntax, const FxFunction& f, size_t i, std::vector<TextEdit>& edits) {
    const auto& t = syntax.tokens;
    if (i + 3 >= f.body.end || !t[i].isIdent() || !t[i + 1].is("(") || !t[i + 2].isIdent() || !t[i + 3].is(")") || t[i - 1].is(".")) return;
    BasicType to = describeBasicType(syntax.resolveType(t[i].text));
    auto from = declaredVariable(syntax, f, t[i + 2].text, i);
    if (!to.ok || !from || (from->dims.empty() && !syntax.findStruct(syntax.resolveType(from->type)))) return;
    std::vector<AggregateComponent> source;
    if (!aggregateComponents(syntax, from->type, from->dims, t[i + 2].text, false, source) || source.size() != size_t(to.rows * to.columns)) return;
    std::string text = " " + vectorSpelling(to) + "(";  // the preprocessed text may join it to `return`
    for (size_t k = 0; k < source.size(); ++k) text += (k ? ", " : "") + source[k].access;
    edits.push_back({t[i].offset, t[i + 3].end, text + ")"});
}

// `T(a, x, b)`, T numeric with more than one argument, x an array or struct variable named alone:
// x gives its components in its place (`float4(arr, 0)` of an `int arr[3]`); glslang checks the count.
// An integer or bool matrix named alone is spelled out the same way, in rows.
void expandConstructorArguments(const EffectSyntax& syntax, const FxFunction& f, size_t i, std::vector<TextEdit>& edits) {
    const auto& t = syntax.tokens;
    if (i + 1 >= f.body.end || !t[i].isIdent() || !t[i + 1].is("(") || t[i - 1].is(".") || !describeBasicType(syntax.resolveType(t[i].text)).ok)
        return;
    std::vector<size_t> loneNames;  // arguments that are one identifier
    size_t arguments = 0;
    int depth = 0;
    for (size_t k = i + 1; k < f.body.end; ++k) {
        if (t[k].is("(") || t[k].is("[") || t[k].is("{")) ++depth;
        if (t[k].is(")") || t[k].is("]") || t[k].is("}")) --depth;
        if (depth == 0) break;
        if (depth == 1 && (t[k].is("(") || t[k].is(","))) {
            ++arguments;
            if (t[k + 1].isIdent() && (t[k + 2].is(",") || t[k + 2].is(")"))) loneNames.push_back(k + 1);
        }
    }
    for (size_t n : loneNames) {
        auto from = declaredVariable(syntax, f, t[n].text, i);
        if (!from) continue;
        // An int, uint or bool matrix too, one argument or more: glslang 12 crashes building a
        // vector from one (float4(int2x2), SIGSEGV); a float matrix it takes.
        BasicType b = describeBasicType(syntax.resolveType(from->type));
        const bool nonFloatMatrix = from->dims.empty() && b.ok && b.isMatrix && b.rows > 1 && b.columns > 1 && b.scalar != "float" &&
                                    b.scalar != "half";
        const bool aggregate = !from->dims.empty() || syntax.findStruct(syntax.resolveType(from->type));
        if (!nonFloatMatrix && (!aggregate || arguments < 2)) continue;  // one aggregate argument: rewriteConstructor's
        std::vector<AggregateComponent> parts;
        if (!aggregateComponents(syntax, from->type, from->dims, t[n].text, false, parts)) continue;
        std::string text;
        for (size_t k = 0; k < parts.size(); ++k) text += (k ? ", " : "") + parts[k].access;
        edits.push_back({t[n].offset, t[n].end, text});
    }
}

// The vector an initializer's cast operand evaluates to, spelled so that repeating it is harmless:
// a constructor of literals and names (`uint4(4, 4, 4, 4)`) or a variable (`v`), ending at `end`;
// its component count, or 0.
int repeatableVectorComponents(const EffectSyntax& syntax, const FxFunction* f, size_t first, size_t end) {
    const auto& t = syntax.tokens;
    if (end == first + 1 && t[first].isIdent()) {
        auto v = f ? declaredVariable(syntax, *f, t[first].text, first) : std::nullopt;
        std::string type;
        if (v && v->dims.empty()) type = v->type;
        for (const auto& g : syntax.globals)
            if (!v && g.name == t[first].text && g.arrayDims.empty()) type = g.type;
        BasicType b = describeBasicType(syntax.resolveType(type));
        return b.ok && !b.isMatrix ? b.rows * b.columns : 0;
    }
    if (end < first + 3 || !t[first].isIdent() || !t[first + 1].is("(") || !t[end - 1].is(")")) return 0;
    for (size_t k = first + 2; k + 1 < end; ++k)
        if (!(t[k].isIdent() || t[k].kind == Token::Kind::Number || t[k].is(",") || t[k].is("-") || t[k].is("."))) return 0;
    BasicType b = describeBasicType(syntax.resolveType(t[first].text));
    return b.ok && !b.isMatrix ? b.rows * b.columns : 0;
}

// `T a[N] = (S[N]) e;` as a local declaration statement (not static), e any expression but an array
// or struct variable, N at most 4: the DirectX SDK's skinning idiom `float w[4] =
// (float[4])i.BlendWeights;`, `int idx[4] = (int[4])D3DCOLORtoUBYTE4(c);`. e is evaluated once into
// a vector of N components (fxc's cast: conversion, truncation) declared just before, which the
// array's initializer list reads. `cast` is the '(' of the cast, `stop` the ';'.
void declareThroughVector(const EffectSyntax& syntax, const FxFunction& f, size_t cast, size_t stop, const std::string& scalar, int n,
                          std::vector<TextEdit>& edits) {
    const auto& t = syntax.tokens;
    if (n > 4 || cast < 6 || !t[cast - 2].is("]") || !t[cast - 4].is("[") || !t[cast - 5].isIdent()) return;
    if (stop == cast + 7 && t[cast + 6].isIdent()) {  // a lone name: an array or struct is glslang's (or the other rewrites')
        auto v = declaredVariable(syntax, f, t[cast + 6].text, cast + 6);
        if (!v || !v->dims.empty() || syntax.findStruct(syntax.resolveType(v->type))) return;
    }
    size_t start = cast - 5;  // back over the type and modifiers to the statement's start
    while (start > f.body.begin && t[start - 1].isIdent()) --start;
    if (start == cast - 5 || !(t[start - 1].is(";") || t[start - 1].is("{") || t[start - 1].is("}"))) return;
    for (size_t k = start; k < cast - 5; ++k)
        if (t[k].is("static")) return;
    const std::string vector = scalar + std::to_string(n), temp = "fxport_cast_" + std::to_string(cast);
    edits.push_back({t[start].offset, t[start].offset, vector + " " + temp + " = (" + vector + ")(" + syntax.text({cast + 6, stop}) + "); "});
    std::string list = "{";
    for (int k = 0; k < n; ++k) list += (k ? ", " : " ") + temp + "[" + std::to_string(k) + "]";
    edits.push_back({t[cast].offset, t[stop - 1].end, list + " }"});
}

// Whether tokens [first, end) are a scalar that can be repeated without changing what the code does:
// a number, negated or not, or a variable declared scalar (local or global, not an array).
bool repeatableScalar(const EffectSyntax& syntax, const FxFunction* f, size_t first, size_t end) {
    const auto& t = syntax.tokens;
    if (end == first + 2 && t[first].is("-")) ++first;
    if (end != first + 1) return false;
    if (t[first].kind == Token::Kind::Number) return true;
    if (!t[first].isIdent()) return false;
    auto v = f ? declaredVariable(syntax, *f, t[first].text, first) : std::nullopt;
    std::string type;
    if (v && v->dims.empty()) type = v->type;
    for (const auto& g : syntax.globals)
        if (!v && g.name == t[first].text && g.arrayDims.empty()) type = g.type;
    BasicType b = describeBasicType(syntax.resolveType(type));
    return b.ok && b.rows * b.columns == 1;
}

// A brace list for an array of `dims` whose every element is `element`: `{ { e, e }, { e, e } }`.
std::string repeatedList(const std::vector<int>& dims, size_t level, const std::string& element) {
    if (level == dims.size()) return element;
    std::string list = "{";
    for (int k = 0; k < dims[level]; ++k) list += (k ? ", " : " ") + repeatedList(dims, level + 1, element);
    return list + " }";
}

// `= (T[N]...) s;` with s a scalar (`float4 a[4] = (float4[4])0;`): fxc fills every element from
// the scalar, where glslang reads the cast as an array constructor of one argument and refuses it.
// In an initializer the cast becomes the list of (T)(s); in the statement `y = (T[N]) s;`, one
// assignment per element. Returns whether it rewrote the cast at i.
bool rewriteScalarToArrayCast(const EffectSyntax& syntax, const FxFunction* f, size_t i, size_t end, std::vector<TextEdit>& edits) {
    const auto& t = syntax.tokens;
    auto cast = castAt(syntax, i, end);
    if (!cast || cast->first.dims.empty()) return false;
    const Declared& to = cast->first;
    BasicType element = describeBasicType(syntax.resolveType(to.type));
    if (!element.ok) return false;  // a struct: glslang's
    for (int n : to.dims)
        if (n < 1) return false;
    const size_t first = cast->second + 1;
    size_t stop = first;
    while (stop < end && !t[stop].is(";")) ++stop;
    if (stop >= end || !repeatableScalar(syntax, f, first, stop)) return false;
    const std::string value = "(" + to.type + ")(" + syntax.text({first, stop}) + ")";
    const bool statement = f && i >= 3 && t[i - 2].isIdent() && (t[i - 3].is(";") || t[i - 3].is("{") || t[i - 3].is("}"));
    if (!statement) {
        edits.push_back({t[i].offset, t[stop - 1].end, repeatedList(to.dims, 0, value)});
        return true;
    }
    auto y = declaredVariable(syntax, *f, t[i - 2].text, i - 2);
    if (!y || y->dims != to.dims) return false;
    size_t count = 1;
    for (int n : to.dims) count *= size_t(n);
    std::string text;
    for (size_t k = 0; k < count; ++k) {
        std::string access = t[i - 2].text;
        size_t rest = k, stride = count;
        for (int n : to.dims) {
            stride /= size_t(n);
            access += "[" + std::to_string(rest / stride) + "]";
            rest %= stride;
        }
        text += access + " = " + value + "; ";
    }
    edits.push_back({t[i - 2].offset, t[stop].end, text});
    return true;
}

// `= (S[N]) e;`, S a scalar type and e a vector of at least N components (SubD11: `static const
// uint Val[4] = (uint[4])uint4(4, 4, 4, 4);`): glslang reads the cast as an array constructor of one
// argument and refuses it. The initializer becomes the list of e's first N components, converted.
void rewriteVectorToArrayInitializers(const EffectSyntax& syntax, const FxFunction* f, size_t begin, size_t end, std::vector<TextEdit>& edits) {
    const auto& t = syntax.tokens;
    for (size_t i = begin + 1; i + 6 < end; ++i) {
        if (t[i - 1].is("=") && rewriteScalarToArrayCast(syntax, f, i, end, edits)) continue;
        if (!t[i - 1].is("=") || !t[i].is("(") || !t[i + 1].isIdent() || !t[i + 2].is("[") || t[i + 3].kind != Token::Kind::Number ||
            !t[i + 4].is("]") || !t[i + 5].is(")"))
            continue;
        BasicType to = describeBasicType(syntax.resolveType(t[i + 1].text));
        const int n = std::atoi(t[i + 3].text.c_str());
        if (!to.ok || to.rows * to.columns != 1 || n < 1) continue;
        size_t stop = i + 6;
        for (int depth = 0; stop < end && !(depth == 0 && t[stop].is(";")); ++stop)
            depth += t[stop].is("(") ? 1 : t[stop].is(")") ? -1 : 0;
        if (stop >= end) continue;
        if (repeatableVectorComponents(syntax, f, i + 6, stop) < n) {
            if (f) declareThroughVector(syntax, *f, i, stop, to.scalar, n, edits);
            continue;
        }
        const std::string operand = "(" + syntax.text({i + 6, stop}) + ")";
        std::string list = "{";
        for (int k = 0; k < n; ++k) list += (k ? ", (" : " (") + to.scalar + ")" + operand + "[" + std::to_string(k) + "]";
        edits.push_back({t[i].offset, t[stop - 1].end, list + " }"});
    }
}

void rewriteIn(const EffectSyntax& syntax, const FxFunction& f, std::vector<TextEdit>& edits) {
    const auto& t = syntax.tokens;
    for (size_t i = f.body.begin + 1; i + 2 < f.body.end; ++i) {
        rewriteConstructor(syntax, f, i, edits);
        expandConstructorArguments(syntax, f, i, edits);
        auto cast = castAt(syntax, i, f.body.end);
        if (!cast) continue;
        const Declared& to = cast->first;
        size_t x = cast->second + 1;  // the cast's operand: a variable, alone
        if (x + 1 >= f.body.end || !t[x].isIdent() || t[x + 1].is(".") || t[x + 1].is("[") || t[x + 1].is("(")) continue;
        if (t[i - 1].isIdent() && !t[i - 1].is("return")) continue;  // a call's parenthesis
        auto from = declaredVariable(syntax, f, t[x].text, i);
        if (!from) continue;
        const bool fromAggregate = !from->dims.empty() || syntax.findStruct(syntax.resolveType(from->type));
        const bool toAggregate = !to.dims.empty() || syntax.findStruct(syntax.resolveType(to.type));
        if (!fromAggregate && !toAggregate) continue;  // vectors and matrices: glslang's and the shape checks'
        // Objects (a texture member) count as one component each where the cast makes an aggregate.
        std::vector<AggregateComponent> source, target;
        if (!aggregateComponents(syntax, from->type, from->dims, t[x].text, false, source, toAggregate) ||
            !aggregateComponents(syntax, to.type, to.dims, "", false, target, toAggregate) || source.size() < target.size())
            continue;
        // A matrix cast to takes exactly its count when it has more than one row; a matrix cast from,
        // when it has more than one row and column (fxc X3017; float4x1 to int[3] is taken).
        auto matrixOf = [&](const Declared& d, int minColumns) {
            BasicType b = describeBasicType(syntax.resolveType(d.type));
            return d.dims.empty() && b.ok && b.isMatrix && b.rows > 1 && b.columns >= minColumns;
        };
        if ((matrixOf(*from, 2) || matrixOf(to, 1)) && source.size() != target.size()) continue;
        if (!toAggregate) {
            std::string text = " " + vectorSpelling(describeBasicType(syntax.resolveType(to.type))) + "(";
            for (size_t k = 0; k < target.size(); ++k) text += (k ? ", " : "") + source[k].access;
            edits.push_back({t[i].offset, t[x].end, text + ")"});
            continue;
        }
        // `y = (T) x;` at a statement's start, y declared as T.
        if (i < 2 || !t[i - 1].is("=") || !t[i - 2].isIdent() || !t[x + 1].is(";")) continue;
        if (i >= 3 && !(t[i - 3].is(";") || t[i - 3].is("{") || t[i - 3].is("}"))) continue;
        auto y = declaredVariable(syntax, f, t[i - 2].text, i - 2);
        if (!y || syntax.resolveType(y->type) != syntax.resolveType(to.type) || y->dims != to.dims) continue;
        std::vector<AggregateComponent> lhs;
        if (!aggregateComponents(syntax, y->type, y->dims, t[i - 2].text, false, lhs, true) || lhs.size() != target.size()) continue;
        std::string text;
        bool objectsMatch = true;
        for (size_t k = 0; k < lhs.size(); ++k) {
            if (lhs[k].object || source[k].object) {  // an object takes only an object of its type
                objectsMatch = objectsMatch && lhs[k].object && source[k].object && lhs[k].scalar == source[k].scalar;
                text += lhs[k].access + " = " + source[k].access + "; ";
            } else {
                text += lhs[k].access + " = (" + lhs[k].scalar + ")" + source[k].access + "; ";
            }
        }
        if (objectsMatch) edits.push_back({t[i - 2].offset, t[x + 1].end, text});
    }
}

}  // namespace

std::vector<TextEdit> componentwiseCasts(const EffectSyntax& syntax) {
    std::vector<TextEdit> edits;
    for (const auto& f : syntax.functions)
        if (!f.body.empty()) {
            rewriteIn(syntax, f, edits);
            rewriteVectorToArrayInitializers(syntax, &f, f.body.begin, f.body.end, edits);
        }
    for (const auto& g : syntax.globals)
        if (!g.initializer.empty()) rewriteVectorToArrayInitializers(syntax, nullptr, g.initializer.begin - 1, g.initializer.end + 1, edits);
    return edits;
}

}  // namespace fxport::xlate
