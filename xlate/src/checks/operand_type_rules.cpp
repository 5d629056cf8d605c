// Operands whose type fxc refuses where glslang's HLSL front end converts them silently. Each is
// judged only where the operand's type is evident (expression_types.h):
//  - asint / asuint / asfloat of one argument take float, int or uint components: a bool or a
//    double argument has no matching overload (fxc X3013; vkd3d's asint, asuint, asfloat);
//  - dst takes a scalar or a 4-component vector: float1, float2, a matrix ... are refused
//    (X3013; vkd3d's distance);
//  - an element-wise intrinsic (step, ldexp, lerp, clamp ...) with a matrix argument cannot take a
//    vector argument of another number of components, a float1 included: there is no implicit
//    conversion between them (X3017; vkd3d's step, ldexp);
//  - the bitwise operators `<<`, `>>`, `&`, `|`, `^` need integer operands: a float operand is
//    refused (X3082; vkd3d's bitwise). Judged where an operand is one name or literal.
#include "hlsl/call_arguments.h"
#include "hlsl/expression_types.h"
#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

bool isOneOf(const std::string& s, std::initializer_list<const char*> names) {
    for (const char* n : names)
        if (s == n) return true;
    return false;
}

std::string describe(const ExpressionType& type) {
    return type.vector1 ? spellType(type.basic) + "1" : spellType(type.basic);
}

bool isFloatScalarType(const std::string& s) { return isOneOf(s, {"float", "half", "double", "min16float", "min10float"}); }

class OperandTypeRules : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& f : syntax_.functions) {
            for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
                if (t_[i].isIdent() && t_[i + 1].is("(") && !(i > 0 && t_[i - 1].is(".")) && !syntax_.findFunction(t_[i].text)) call(f, i);
                if (t_[i].kind != Token::Kind::Punct) continue;
                if (isOneOf(t_[i].text, {"&", "|", "^"})) bitwise(f, i, i);
                // The lexer keeps `<<` and `>>` as two tokens (they close templates and annotations).
                bool shift = (t_[i].is("<") || t_[i].is(">")) && t_[i + 1].is(t_[i].text) && t_[i].end == t_[i + 1].offset &&
                             i + 2 < f.body.end && !t_[i + 2].is("=") && !t_[i + 2].is(t_[i].text) && !(i > 0 && t_[i - 1].is(t_[i].text));
                if (shift) {
                    bitwise(f, i, i + 1);
                    ++i;
                }
            }
        }
    }

private:
    std::optional<ExpressionType> typeOf(const FxFunction& f, size_t b, size_t e) const {
        auto type = expressionType(syntax_, f, b, e);
        if (!type || !type->isNumeric()) return std::nullopt;
        return type;
    }

    void call(const FxFunction& f, size_t at) {
        const std::string& name = t_[at].text;
        auto args = callArgumentSpans(t_, at + 1, f.body.end);
        std::vector<std::optional<ExpressionType>> types;
        for (const auto& [b, e] : args) types.push_back(typeOf(f, b, e));
        if (isOneOf(name, {"asint", "asuint", "asfloat"}) && args.size() == 1 && types[0] &&
            (types[0]->basic.scalar == "bool" || types[0]->basic.scalar == "double"))
            return report("'" + name + "': no matching 1 parameter intrinsic function for an argument of type '" + describe(*types[0]) + "' (fxc X3013)", at);
        if (name == "dst" && args.size() == 2) {
            for (const auto& type : types)
                if (type && (type->basic.isMatrix || type->vector1 || (type->basic.columns != 1 && type->basic.columns != 4)))
                    return report("'dst': no matching 2 parameter intrinsic function for an argument of type '" + describe(*type) +
                                      "' (a scalar or a 4-component vector; fxc X3013)",
                                  at);
        }
        if (isOneOf(name, {"step", "ldexp", "lerp", "clamp", "max", "min", "mad", "smoothstep", "pow", "fmod"})) {
            const ExpressionType* matrix = nullptr;
            for (const auto& type : types)
                if (type && type->basic.isMatrix && !type->keptMatrix) matrix = &*type;
            if (!matrix) return;
            for (const auto& type : types)
                if (type && !type->basic.isMatrix && (type->vector1 || (type->basic.columns > 1 && type->basic.columns != matrix->basic.rows * matrix->basic.columns)))
                    return report("'" + name + "': cannot implicitly convert from '" + describe(*type) + "' to '" + describe(*matrix) + "' (fxc X3017)", at);
        }
    }

    // `a >> b` (the operator's tokens [op, opLast]) where a or b is one name or literal of a float type.
    void bitwise(const FxFunction& f, size_t op, size_t opLast) {
        if (op <= f.body.begin || opLast + 2 >= f.body.end) return;
        for (size_t side : {op - 1, opLast + 1}) {
            if (!(t_[side].isIdent() || t_[side].kind == Token::Kind::Number)) continue;
            // The operand must be the whole side: `s.f >> 2`, `u >> s.f`, `u & f(x)`, `u & a[0]` are left alone.
            if (side < op ? t_[side - 1].is(".") : (t_[side + 1].is(".") || t_[side + 1].is("(") || t_[side + 1].is("["))) continue;
            auto type = typeOf(f, side, side + 1);
            if (type && isFloatScalarType(type->basic.scalar))
                return report("'" + t_[op].text + (op == opLast ? "" : t_[op].text) + "': int or unsigned int type required, '" + t_[side].text + "' is '" + describe(*type) + "' (fxc X3082)", op);
        }
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findOperandTypeErrors(const EffectSyntax& syntax, const SourceMap& map) {
    OperandTypeRules check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
