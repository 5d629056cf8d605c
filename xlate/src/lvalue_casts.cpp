// See lvalue_casts.h: `(T) target = value;` as fxc means it, and its SM4+ rule.
#include "lvalue_casts.h"

#include <optional>
#include <string>

#include "fxc_checks.h"
#include "variable_declarations.h"

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

std::optional<LvalueCast> lvalueCastAt(const EffectSyntax& syntax, const FxFunction& f, size_t i) {
    const auto& t = syntax.tokens;
    if (!t[i].is("(") || !(i == f.body.begin || t[i - 1].is(";") || t[i - 1].is("{") || t[i - 1].is("}"))) return std::nullopt;
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
    int depth = 0;
    for (++j; j < f.body.end; ++j) {
        if (t[j].is("(") || t[j].is("[") || t[j].is("{")) ++depth;
        else if (t[j].is(")") || t[j].is("]") || t[j].is("}")) --depth;
        else if (depth == 0 && t[j].is(";")) break;
        if (depth < 0) return std::nullopt;
    }
    if (j >= f.body.end) return std::nullopt;
    c.semicolon = j;
    return c;
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
        } else {
            continue;  // a partial matrix assignment: left to glslang
        }
        edits.push_back({t[c.first].offset, t[c.equals].end, " " + lhs + " = " + value});
        edits.push_back({t[c.semicolon].offset, t[c.semicolon].offset, ")"});
    }
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
