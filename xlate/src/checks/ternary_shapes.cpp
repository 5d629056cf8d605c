// fxc's shape rules for `cond ? a : b` (vkd3d's ternary pins them); glslang's HLSL front end
// converts whatever it is given. Judged where the three operands are plain names (or number
// literals) whose declared types tell their shapes; anything else is left to glslang:
//  - a condition of several components selects per component: an operand of several components
//    has the condition's shape (float4 and float1x4 count as one shape), else fxc refuses;
//  - with a one-component condition, two matrices must fit one in the other (float2x4 and
//    float3x2 do not);
//  - objects (textures, samplers) take a one-component condition, both of the same type; an
//    object is no condition.
#include <optional>

#include "checks/fxc_checks.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

struct Shape {
    bool object = false;
    std::string type;  // as declared
    int rows = 1, columns = 1;
    int components() const { return rows * columns; }
    bool sameShape(const Shape& o) const { return rows == o.rows && columns == o.columns; }
};

bool isBoundary(const Token& t) {
    for (const char* s : {"(", "=", ",", "return", ";", "{", "}", "["})
        if (t.is(s)) return true;
    return false;
}

bool endsOperand(const Token& t) {
    for (const char* s : {")", ";", ",", "]"})
        if (t.is(s)) return true;
    return false;
}

class TernaryShapes : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& f : syntax_.functions)
            for (size_t q = f.body.begin + 1; q + 4 < f.body.end; ++q)  // t_[body.begin - 1] is the `{`
                if (t_[q].is("?") && isBoundary(t_[q - 2]) && t_[q + 2].is(":") && endsOperand(t_[q + 4])) judge(f, q);
    }

private:
    void judge(const FxFunction& f, size_t q) {
        auto cond = shapeOf(f, q - 1), a = shapeOf(f, q + 1), b = shapeOf(f, q + 3);
        if (!cond || !a || !b) return;
        if (cond->object) return report("an object ('" + t_[q - 1].text + "', " + cond->type + ") cannot be the condition of '?:'", q - 1);
        if (a->object || b->object) {
            if (!a->object || !b->object || a->type != b->type)
                return report("the two results of '?:' are '" + a->type + "' and '" + b->type + "': objects must be of one type", q);
            if (cond->components() > 1)
                return report("'?:' chooses between objects with a condition of one component, not '" + cond->type + "'", q - 1);
            return;
        }
        if (cond->components() > 1) {
            for (const Shape* s : {&*a, &*b})
                if (s->components() > 1 && !s->sameShape(*cond))
                    return report("'?:' with condition '" + t_[q - 1].text + "' (" + cond->type + ") selects per component: '" + s->type +
                                      "' is not of its shape",
                                  q);
            return;
        }
        bool aFits = a->rows <= b->rows && a->columns <= b->columns, bFits = b->rows <= a->rows && b->columns <= a->columns;
        if (a->rows > 1 && b->rows > 1 && !aFits && !bFits)
            report("the two results of '?:' are '" + a->type + "' and '" + b->type + "': neither matrix fits in the other", q);
    }

    // The declared type of the name at `at` in `f` (or a number literal's), when evident.
    std::optional<Shape> shapeOf(const FxFunction& f, size_t at) const {
        const Token& t = t_[at];
        if (t.kind == Token::Kind::Number) return Shape{false, "literal", 1, 1};
        if (!t.isIdent()) return std::nullopt;
        std::string type = declaredType(f, at);
        if (type.empty()) return std::nullopt;
        BasicType b = describeBasicType(syntax_.resolveType(type));
        if (b.ok) return b.isMatrix ? Shape{false, type, b.rows, b.columns} : Shape{false, type, 1, b.columns};
        if (syntax_.findTexture(t.text) || syntax_.findSampler(t.text)) return Shape{true, type, 1, 1};
        return std::nullopt;
    }

    std::string declaredType(const FxFunction& f, size_t at) const {
        const std::string& name = t_[at].text;
        for (size_t i = at; i-- > f.body.begin + 1;) {  // the nearest earlier `Type name` in the body
            if (t_[i].text != name || !t_[i].isIdent()) continue;
            if (t_[i - 1].isIdent() && !t_[i - 1].is("return")) return t_[i - 1].text;
            if (t_[i - 1].is(",") || t_[i - 1].is(">")) return {};  // `float4 a, name;` or `vector<...> name`: not evident
        }
        for (const auto& p : f.parameters)
            if (p.name == name) return p.arrayDims.empty() ? p.type : std::string();
        for (const auto& g : syntax_.globals)
            if (g.name == name) return g.arrayDims.empty() ? g.type : std::string();
        if (const FxTexture* tex = syntax_.findTexture(name)) return tex->type;
        if (const FxSampler* s = syntax_.findSampler(name)) return s->type;
        return {};
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findTernaryShapeErrors(const EffectSyntax& syntax, const SourceMap& map) {
    TernaryShapes check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
