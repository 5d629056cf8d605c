// See componentwise_casts.h.
#include "componentwise_casts.h"

#include <cstdlib>
#include <optional>
#include <string>

#include "aggregate_components.h"
#include "hlsl_types.h"
#include "variable_declarations.h"

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

// `y = x;` at a statement's start, y and x arrays or structs of other types whose components
// match one for one in type: one assignment per component.
void rewriteEqualAssignment(const EffectSyntax& syntax, const FxFunction& f, size_t i, std::vector<TextEdit>& edits) {
    const auto& t = syntax.tokens;
    if (i + 3 >= f.body.end || !t[i].isIdent() || !t[i + 1].is("=") || !t[i + 2].isIdent() || !t[i + 3].is(";")) return;
    if (!(t[i - 1].is(";") || t[i - 1].is("{") || t[i - 1].is("}"))) return;
    auto y = declaredVariable(syntax, f, t[i].text, i);
    auto x = declaredVariable(syntax, f, t[i + 2].text, i);
    auto aggregate = [&](const Declared& d) { return !d.dims.empty() || syntax.findStruct(syntax.resolveType(d.type)); };
    if (!y || !x || !aggregate(*y) || !aggregate(*x)) return;
    if (syntax.resolveType(y->type) == syntax.resolveType(x->type) && y->dims == x->dims) return;  // glslang's
    std::vector<AggregateComponent> lhs, rhs;
    if (!aggregateComponents(syntax, y->type, y->dims, t[i].text, false, lhs) || !aggregateComponents(syntax, x->type, x->dims, t[i + 2].text, false, rhs) ||
        lhs.size() != rhs.size())
        return;
    std::string text;
    for (size_t k = 0; k < lhs.size(); ++k) {
        if (lhs[k].scalar != rhs[k].scalar) return;  // fxc converts only between equal component types here
        text += lhs[k].access + " = " + rhs[k].access + "; ";
    }
    edits.push_back({t[i].offset, t[i + 3].end, text});
}

void rewriteIn(const EffectSyntax& syntax, const FxFunction& f, std::vector<TextEdit>& edits) {
    const auto& t = syntax.tokens;
    for (size_t i = f.body.begin + 1; i + 2 < f.body.end; ++i) {
        rewriteConstructor(syntax, f, i, edits);
        rewriteEqualAssignment(syntax, f, i, edits);
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
        std::vector<AggregateComponent> source, target;
        if (!aggregateComponents(syntax, from->type, from->dims, t[x].text, false, source) || !aggregateComponents(syntax, to.type, to.dims, "", false, target) ||
            source.size() < target.size())
            continue;
        // A matrix of more than one row on either side takes exactly its count (fxc X3017).
        auto manyRows = [&](const Declared& d) {
            BasicType b = describeBasicType(syntax.resolveType(d.type));
            return d.dims.empty() && b.ok && b.isMatrix && b.rows > 1;
        };
        if ((manyRows(*from) || manyRows(to)) && source.size() != target.size()) continue;
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
        if (!aggregateComponents(syntax, y->type, y->dims, t[i - 2].text, false, lhs) || lhs.size() != target.size()) continue;
        std::string text;
        for (size_t k = 0; k < lhs.size(); ++k) text += lhs[k].access + " = (" + lhs[k].scalar + ")" + source[k].access + "; ";
        edits.push_back({t[i - 2].offset, t[x + 1].end, text});
    }
}

}  // namespace

std::vector<TextEdit> componentwiseCasts(const EffectSyntax& syntax) {
    std::vector<TextEdit> edits;
    for (const auto& f : syntax.functions)
        if (!f.body.empty()) rewriteIn(syntax, f, edits);
    return edits;
}

}  // namespace fxport::xlate
