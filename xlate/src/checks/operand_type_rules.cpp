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
//    refused (X3082; vkd3d's bitwise), in `<<=` and `>>=` too (vkd3d's bitwise-assignment). Judged
//    where an operand is one name or literal;
//  - `/` and `%` between signed minimum-precision integers (min16int, min12int) are not supported
//    (vkd3d's arithmetic-int-uniform; min16uint divides, and so does a min16int by an int).
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
                if (isOneOf(t_[i].text, {"/", "%", "/=", "%="})) signedMinPrecisionDivision(f, i);
                // The lexer keeps `<<` and `>>` as two tokens (they close templates and annotations).
                bool shift = (t_[i].is("<") || t_[i].is(">")) && t_[i + 1].is(t_[i].text) && t_[i].end == t_[i + 1].offset &&
                             i + 2 < f.body.end && !t_[i + 2].is("=") && !t_[i + 2].is(t_[i].text) && !(i > 0 && t_[i - 1].is(t_[i].text));
                if (shift) {
                    bitwise(f, i, i + 1);
                    ++i;
                }
                // `x <<= y` (three tokens) takes the same operands.
                bool shiftAssign = (t_[i].is("<") || t_[i].is(">")) && t_[i + 1].is(t_[i].text) && i + 2 < f.body.end && t_[i + 2].is("=") &&
                                   t_[i].end == t_[i + 1].offset && t_[i + 1].end == t_[i + 2].offset && !(i > 0 && t_[i - 1].is(t_[i].text));
                if (shiftAssign) {
                    bitwise(f, i, i + 2);
                    i += 2;
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

    std::string spelled(size_t first, size_t last) const {
        std::string out;
        for (size_t k = first; k <= last; ++k) out += t_[k].text;
        return out;
    }

    // `a / b` where both operands are signed minimum-precision integers (in the common type of a
    // min16int and an int, the division is a 32-bit one). An operand is judged when it is one name
    // or a member or swizzle of one (`u.x`), and must end where the operator's neighbours end.
    void signedMinPrecisionDivision(const FxFunction& f, size_t op) {
        if (op < f.body.begin + 2 || op + 2 >= f.body.end || !t_[op - 1].isIdent() || !t_[op + 1].isIdent()) return;
        const size_t leftBegin = t_[op - 2].is(".") ? op - 3 : op - 1;
        if (leftBegin <= f.body.begin || t_[leftBegin - 1].is(".") || !t_[leftBegin].isIdent()) return;
        const size_t rightEnd = t_[op + 2].is(".") ? op + 4 : op + 2;
        if (rightEnd >= f.body.end || t_[rightEnd].is(".") || t_[rightEnd].is("(") || t_[rightEnd].is("[")) return;
        auto left = typeOf(f, leftBegin, op), right = typeOf(f, op + 1, rightEnd);
        auto signedMin = [](const std::optional<ExpressionType>& t) { return t && isOneOf(t->basic.scalar, {"min16int", "min12int"}); };
        if (signedMin(left) && signedMin(right))
            report("'" + t_[op].text + "': division of signed minimum-precision integers ('" + describe(*left) + "' by '" + describe(*right) +
                       "') is not supported by fxc",
                   op);
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
                return report("'" + spelled(op, opLast) + "': int or unsigned int type required, '" + t_[side].text + "' is '" + describe(*type) + "' (fxc X3082)", op);
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
