// See lvalue_casts.h: `(T) target = value;` as fxc means it, and its SM4+ rule.
#include "rewrite/lvalue_casts.h"

#include <cstdlib>
#include <cstring>
#include <optional>
#include <string>

#include "hlsl/aggregate_components.h"
#include "checks/fxc_checks.h"
#include "hlsl/variable_declarations.h"

namespace fxport::xlate {

namespace {

int componentCount(const BasicType& b) { return b.rows * b.columns; }

std::string spell(const BasicType& b) {
    if (b.isMatrix) return b.scalar + std::to_string(b.rows) + "x" + std::to_string(b.columns);
    return b.columns > 1 ? b.scalar + std::to_string(b.columns) : b.scalar;
}

// `half` is a float to every profile fxport compiles for.
std::string componentType(const BasicType& b) { return b.scalar == "half" ? "float" : b.scalar == "dword" ? "uint" : b.scalar; }

std::optional<BasicType> numeric(const EffectSyntax& syntax, const std::string& type) {
    BasicType b = describeBasicType(syntax.resolveType(type));
    if (!b.ok) return std::nullopt;
    return b;
}

// The type of `name(.member)*(.swizzle)?` at tokens [b, e) of `f`.
std::optional<BasicType> targetType(const EffectSyntax& syntax, const FxFunction& f, size_t b, size_t e) {
    const auto& t = syntax.tokens;
    auto declared = declaredVariable(syntax, f, t[b].text, b);
    if (!declared || !declared->dims.empty()) return std::nullopt;
    std::string type = declared->type;
    for (size_t i = b + 2; i < e; i += 2) {
        if (const FxStruct* s = syntax.findStruct(syntax.resolveType(type))) {
            std::string next;
            for (const auto& m : s->members)
                if (m.name == t[i].text && m.arrayDims.empty()) next = m.type;
            if (next.empty()) return std::nullopt;
            type = next;
            continue;
        }
        auto v = numeric(syntax, type);
        const std::string& sw = t[i].text;
        if (!v || v->isMatrix || i + 1 != e || sw.size() > 4 ||
            (sw.find_first_not_of("xyzw") != std::string::npos && sw.find_first_not_of("rgba") != std::string::npos))
            return std::nullopt;
        v->columns = static_cast<int>(sw.size());
        return v;
    }
    return numeric(syntax, type);
}

// A swizzle's components (0..3), or nothing.
std::optional<std::vector<int>> swizzleComponents(const std::string& sw) {
    if (sw.empty() || sw.size() > 4) return std::nullopt;
    for (const char* set : {"xyzw", "rgba"}) {
        std::vector<int> out;
        for (char ch : sw)
            if (const char* at = std::strchr(set, ch); at && ch) out.push_back(int(at - set));
        if (out.size() == sw.size()) return out;
    }
    return std::nullopt;
}

// What a parenthesised cast reaches: the variable (with members), the components of it still
// visible (indices into it), and the casts met, outermost first.
struct CastView {
    size_t target = 0, targetEnd = 0;
    std::vector<int> components;
    std::vector<BasicType> casts;
};

// `( (T)+ X ) . swizzle` at j, X a variable path or again such a form; `j` moves past it.
std::optional<CastView> castView(const EffectSyntax& syntax, const FxFunction& f, size_t& j) {
    const auto& t = syntax.tokens;
    if (j >= f.body.end || !t[j].is("(")) return std::nullopt;
    ++j;
    std::vector<BasicType> casts;
    while (j + 2 < f.body.end && t[j].is("(") && t[j + 1].isIdent() && t[j + 2].is(")")) {
        auto b = numeric(syntax, t[j + 1].text);
        if (!b || b->isMatrix) return std::nullopt;
        casts.push_back(*b);
        j += 3;
    }
    if (casts.empty() || j >= f.body.end) return std::nullopt;
    CastView view;
    if (t[j].is("(")) {
        auto inner = castView(syntax, f, j);
        if (!inner) return std::nullopt;
        view = *inner;
    } else if (t[j].isIdent()) {
        view.target = j++;
        while (j + 1 < f.body.end && t[j].is(".") && t[j + 1].isIdent() && !swizzleComponents(t[j + 1].text)) j += 2;
        view.targetEnd = j;
        auto type = targetType(syntax, f, view.target, view.targetEnd);
        if (!type || type->isMatrix) return std::nullopt;
        for (int k = 0; k < type->columns; ++k) view.components.push_back(k);
    } else {
        return std::nullopt;
    }
    // The casts, innermost first, keep the first components.
    for (auto k = casts.rbegin(); k != casts.rend(); ++k) {
        if (k->columns > int(view.components.size())) return std::nullopt;
        view.components.resize(size_t(k->columns));
    }
    view.casts.insert(view.casts.begin(), casts.begin(), casts.end());
    if (j + 2 >= f.body.end || !t[j].is(")") || !t[j + 1].is(".")) return std::nullopt;
    auto sw = swizzleComponents(t[j + 2].text);
    if (!sw) return std::nullopt;
    std::vector<int> picked;
    for (int c : *sw) {
        if (c >= int(view.components.size())) return std::nullopt;
        picked.push_back(view.components[size_t(c)]);
    }
    view.components = picked;
    j += 3;
    return view;
}

// `((int4) f).xy = v;` at i: the target and value, in LvalueCast's swizzledTarget/assignedType.
// The `;` that ends the statement from token `from`, outside brackets; none if a bracket closes first.
std::optional<size_t> statementEnd(const std::vector<Token>& t, size_t from, size_t end) {
    int depth = 0;
    for (size_t j = from; j < end; ++j) {
        if (t[j].is("(") || t[j].is("[") || t[j].is("{")) ++depth;
        else if (t[j].is(")") || t[j].is("]") || t[j].is("}")) --depth;
        else if (depth == 0 && t[j].is(";")) return j;
        if (depth < 0) return std::nullopt;
    }
    return std::nullopt;
}

std::optional<LvalueCast> parenthesisedCastAt(const EffectSyntax& syntax, const FxFunction& f, size_t i) {
    const auto& t = syntax.tokens;
    size_t j = i;
    auto view = castView(syntax, f, j);
    if (!view || j >= f.body.end || !t[j].is("=")) return std::nullopt;
    LvalueCast c;
    c.first = i;
    c.function = &f;
    c.target = view->target;
    c.equals = j;
    c.casts = view->casts;
    auto type = targetType(syntax, f, view->target, view->targetEnd);
    if (!type) return std::nullopt;
    c.targetType = *type;
    for (size_t k = view->target; k < view->targetEnd; ++k) c.swizzledTarget += t[k].text;
    if (type->columns > 1) {
        c.swizzledTarget += ".";
        for (int k : view->components) c.swizzledTarget += "xyzw"[k];
    }
    BasicType assigned = c.casts.front();
    assigned.columns = int(view->components.size());
    c.assignedType = spell(assigned);
    const auto end = statementEnd(t, j + 1, f.body.end);
    if (!end) return std::nullopt;
    c.semicolon = *end;
    return c;
}

std::optional<LvalueCast> lvalueCastAt(const EffectSyntax& syntax, const FxFunction& f, size_t i) {
    const auto& t = syntax.tokens;
    if (!t[i].is("(") || !(i == f.body.begin || t[i - 1].is(";") || t[i - 1].is("{") || t[i - 1].is("}"))) return std::nullopt;
    if (i + 1 < f.body.end && t[i + 1].is("(")) return parenthesisedCastAt(syntax, f, i);
    LvalueCast c;
    c.first = i;
    c.function = &f;
    size_t j = i;
    while (j + 2 < f.body.end && t[j].is("(") && t[j + 1].isIdent() && t[j + 2].is(")")) {
        auto b = numeric(syntax, t[j + 1].text);
        if (!b) return std::nullopt;
        c.casts.push_back(*b);
        j += 3;
    }
    if (c.casts.empty() || j >= f.body.end || !t[j].isIdent()) return std::nullopt;
    c.target = j++;
    while (j + 1 < f.body.end && t[j].is(".") && t[j + 1].isIdent()) j += 2;
    if (j >= f.body.end || !t[j].is("=")) return std::nullopt;
    c.equals = j;
    auto type = targetType(syntax, f, c.target, c.equals);
    if (!type) return std::nullopt;
    c.targetType = *type;
    const auto end = statementEnd(t, j + 1, f.body.end);
    if (!end) return std::nullopt;
    c.semicolon = *end;
    return c;
}

// `(float2x3) g = v;` of a float4x4 g: the rows and columns the cast keeps (its top left) take v,
// converted by the outermost cast: `{ float2x3 fxport_lhs = (float2x3)(v); g[0].xyz = fxport_lhs[0]; ... }`.
// Every cast of the chain must fit in the one inside it. The text before the value and after it.
std::optional<std::pair<std::string, std::string>> partialMatrixAssignment(const LvalueCast& c, const std::string& lhs) {
    BasicType inside = c.targetType;
    if (!inside.isMatrix) return std::nullopt;
    for (auto k = c.casts.rbegin(); k != c.casts.rend(); ++k) {
        if (!k->isMatrix || k->rows > inside.rows || k->columns > inside.columns) return std::nullopt;
        inside = *k;
    }
    const BasicType& outer = c.casts.front();
    std::string before = " { " + spell(outer) + " fxport_lhs = (" + spell(outer) + ")(";
    std::string after = "); ";
    for (int r = 0; r < outer.rows; ++r)
        after += lhs + "[" + std::to_string(r) + "]." + std::string("xyzw").substr(0, size_t(outer.columns)) + " = fxport_lhs[" + std::to_string(r) + "]; ";
    return std::make_pair(before, after + "}");
}

// `(float[2]) p = r;` at a statement's start, p a declared array with at least as many components:
// p's first components take the value's, in fxc's order (array elements, then each one's
// components): `{ float fxport_lhs[2] = r; p[0] = fxport_lhs[0]; p[1] = fxport_lhs[1]; }`.
std::vector<TextEdit> arrayLvalueCasts(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const auto& f : syntax.functions) {
        for (size_t i = f.body.begin + 1; i + 6 < f.body.end; ++i) {
            if (!t[i].is("(") || !(t[i - 1].is(";") || t[i - 1].is("{") || t[i - 1].is("}")) || !t[i + 1].isIdent() || !t[i + 2].is("[")) continue;
            const std::string& type = t[i + 1].text;
            BasicType element = describeBasicType(syntax.resolveType(type));
            if (!element.ok) continue;
            std::vector<int> dims;
            size_t j = i + 2;
            for (; j + 2 < f.body.end && t[j].is("[") && t[j + 1].kind == Token::Kind::Number && t[j + 2].is("]"); j += 3)
                dims.push_back(std::atoi(t[j + 1].text.c_str()));
            if (!t[j].is(")") || !t[j + 1].isIdent() || !t[j + 2].is("=")) continue;
            const size_t name = j + 1, equals = j + 2;
            auto target = declaredVariable(syntax, f, t[name].text, name);
            if (!target || target->dims.empty()) continue;
            size_t semicolon = equals + 1;
            for (int depth = 0; semicolon < f.body.end; ++semicolon) {
                if (t[semicolon].is("(") || t[semicolon].is("[") || t[semicolon].is("{")) ++depth;
                if (t[semicolon].is(")") || t[semicolon].is("]") || t[semicolon].is("}")) --depth;
                if (depth == 0 && t[semicolon].is(";")) break;
            }
            std::vector<AggregateComponent> whole, part;
            if (semicolon >= f.body.end || !aggregateComponents(syntax, target->type, target->dims, t[name].text, false, whole) ||
                !aggregateComponents(syntax, type, dims, "fxport_lhs", false, part) || part.size() > whole.size())
                continue;
            std::string declared = " { " + type + " fxport_lhs";
            for (int d : dims) declared += "[" + std::to_string(d) + "]";
            std::string assignments = "; ";
            for (size_t k = 0; k < part.size(); ++k) assignments += whole[k].access + " = " + part[k].access + "; ";
            edits.push_back({t[i].offset, t[equals].end, declared + " ="});
            edits.push_back({t[semicolon].offset, t[semicolon].end, assignments + "}"});
            i = semicolon;
        }
    }
    return edits;
}

}  // namespace

std::vector<LvalueCast> findLvalueCasts(const EffectSyntax& syntax) {
    std::vector<LvalueCast> out;
    for (const auto& f : syntax.functions)
        for (size_t i = f.body.begin; i < f.body.end; ++i)
            if (auto c = lvalueCastAt(syntax, f, i)) {
                out.push_back(*c);
                i = c->semicolon;
            }
    return out;
}

std::vector<TextEdit> lvalueCastsAsAssignments(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const LvalueCast& c : findLvalueCasts(syntax)) {
        if (!c.swizzledTarget.empty()) {
            edits.push_back({t[c.first].offset, t[c.equals].end, " " + c.swizzledTarget + " = (" + c.assignedType + ")("});
            edits.push_back({t[c.semicolon].offset, t[c.semicolon].offset, ")"});
            continue;
        }
        const BasicType& outer = c.casts.front();
        const BasicType& target = c.targetType;
        std::string lhs;
        for (size_t i = c.target; i < c.equals; ++i) lhs += t[i].text;
        std::string value;
        if (!outer.isMatrix && !target.isMatrix && componentCount(outer) <= componentCount(target)) {
            // The first components of the target take the value, converted by the outermost cast.
            if (componentCount(outer) < componentCount(target)) lhs += "." + std::string("xyzw").substr(0, size_t(componentCount(outer)));
            value = "(" + spell(outer) + ")(";
        } else if (componentCount(outer) == componentCount(target)) {
            value = "(" + spell(target) + ")(" + spell(outer) + ")(";
        } else if (auto m = partialMatrixAssignment(c, lhs)) {
            edits.push_back({t[c.first].offset, t[c.equals].end, m->first});
            edits.push_back({t[c.semicolon].offset, t[c.semicolon].end, m->second});
            continue;
        } else {
            continue;
        }
        edits.push_back({t[c.first].offset, t[c.equals].end, " " + lhs + " = " + value});
        edits.push_back({t[c.semicolon].offset, t[c.semicolon].offset, ")"});
    }
    for (auto& e : arrayLvalueCasts(syntax)) edits.push_back(std::move(e));
    return edits;
}

// In SM4 and later a cast on the left may not change the component type.
std::vector<std::pair<size_t, Diagnostic>> findLvalueCastErrors(const EffectSyntax& syntax, const SourceMap& map) {
    class Check : public FxcCheck {
    public:
        using FxcCheck::FxcCheck;
        void run() {
            const auto casts = findLvalueCasts(syntax_);
            for (const auto& e : compiledEntries()) {
                if (e.profile.major < 4) continue;
                for (const FxFunction* f : reachableFrom(*e.function))
                    for (const LvalueCast& c : casts)
                        if (c.function == f)
                            for (const BasicType& b : c.casts)
                                if (componentType(b) != componentType(c.targetType)) {
                                    report("a cast on the left of '=' may not change the component type ('" + spell(c.targetType) + "' to '" +
                                               spell(b) + "') in " + e.profile.name + " (fxc X3025)",
                                           c.first);
                                    break;
                                }
            }
        }
    };
    Check check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
