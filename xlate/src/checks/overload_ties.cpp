// Calls fxc's overload ranking cannot decide, where glslang picks an overload silently (vkd3d's
// function-overload pins each; fxc X3067 "ambiguous function call"). Two overloads of a name with
// as many parameters tie for a call when every parameter where they differ ties for its argument:
//  - a bool for int and float: neither is closer;
//  - a vector of N components for the vector floatN and a matrix of N components (float2x2 for a
//    float4): fxc converts between them as freely as it takes the vector as it is;
//  - an unsuffixed integer literal (`3`, `-3`) for int and uint of one shape: its sign is
//    unspecified (`3l` reaches the checks as `int(3)`, typed: literal_suffixes.h).
// Judged where the arguments' types are evident (expression_types.h); the other ties fxc knows
// are left to glslang (overload_ambiguity.cpp judges scalars and one-component vectors).
#include <map>

#include "hlsl/call_arguments.h"
#include "hlsl/expression_types.h"
#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

class OverloadTies : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        std::map<std::string, std::vector<const FxFunction*>> byName;
        for (const auto& f : syntax_.functions) byName[f.name].push_back(&f);
        for (const auto& f : syntax_.functions)
            for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
                if (!t_[i].isIdent() || !t_[i + 1].is("(") || (i > 0 && t_[i - 1].is("."))) continue;
                auto it = byName.find(t_[i].text);
                if (it != byName.end() && it->second.size() > 1) call(f, i, it->second);
            }
    }

private:
    void call(const FxFunction& caller, size_t at, const std::vector<const FxFunction*>& overloads) {
        auto args = callArgumentSpans(t_, at + 1, caller.body.end);
        for (size_t a = 0; a < overloads.size(); ++a)
            for (size_t b = 0; b < a; ++b)
                if (ties(caller, args, *overloads[a], *overloads[b]))
                    return report("ambiguous function call: '" + show(*overloads[b]) + "' and '" + show(*overloads[a]) + "' rank alike for these arguments (fxc X3067)", at);
    }

    bool ties(const FxFunction& caller, const std::vector<std::pair<size_t, size_t>>& args, const FxFunction& x, const FxFunction& y) const {
        if (x.parameters.size() != args.size() || y.parameters.size() != args.size()) return false;
        bool differ = false;
        for (size_t k = 0; k < args.size(); ++k) {
            const FxParameter &p = x.parameters[k], &q = y.parameters[k];
            if (!p.arrayDims.empty() || !q.arrayDims.empty()) return false;
            BasicType pt = describeBasicType(syntax_.resolveType(p.type)), qt = describeBasicType(syntax_.resolveType(q.type));
            if (!pt.ok || !qt.ok) {
                if (syntax_.resolveType(p.type) != syntax_.resolveType(q.type)) return false;
                continue;
            }
            if (pt.scalar == qt.scalar && pt.rows == qt.rows && pt.columns == qt.columns && pt.isMatrix == qt.isMatrix) continue;
            differ = true;
            if (!tieFor(caller, args[k], pt, qt) && !tieFor(caller, args[k], qt, pt)) return false;
        }
        return differ;
    }

    bool tieFor(const FxFunction& caller, std::pair<size_t, size_t> arg, const BasicType& p, const BasicType& q) const {
        const bool scalars = !p.isMatrix && !q.isMatrix && p.columns == 1 && q.columns == 1;
        auto type = expressionType(syntax_, caller, arg.first, arg.second);
        if (!type || !type->isNumeric()) return false;
        const BasicType& t = type->basic;
        if (scalars && p.scalar == "int" && q.scalar == "float" && t.scalar == "bool" && !t.isMatrix && t.columns == 1) return true;
        if (intLiteral(arg) && p.rows == q.rows && p.columns == q.columns && p.isMatrix == q.isMatrix && isInt(p.scalar) && isUint(q.scalar))
            return true;
        const int n = t.rows * t.columns;
        return !t.isMatrix && !type->vector1 && t.columns > 1 && p.scalar == q.scalar && !p.isMatrix && p.columns == n && q.isMatrix &&
               q.rows > 1 && q.columns > 1 && q.rows * q.columns == n;
    }

    static bool isInt(const std::string& s) { return s == "int"; }
    static bool isUint(const std::string& s) { return s == "uint" || s == "dword"; }

    // `3`, `0x10`, `-3`: no suffix, no point, no exponent (`3.0` is float, `3u` uint).
    bool intLiteral(std::pair<size_t, size_t> arg) const {
        size_t at = arg.first + (arg.second == arg.first + 2 && t_[arg.first].is("-") ? 1 : 0);
        if (at + 1 != arg.second || t_[at].kind != Token::Kind::Number) return false;
        const std::string& s = t_[at].text;
        const bool hex = s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
        return s.find_first_not_of(hex ? "0123456789abcdefABCDEFxX" : "0123456789") == std::string::npos;
    }

    std::string show(const FxFunction& f) const {
        std::string out = f.name + "(";
        for (size_t k = 0; k < f.parameters.size(); ++k) out += (k ? ", " : "") + f.parameters[k].type;
        return out + ")";
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findOverloadTieErrors(const EffectSyntax& syntax, const SourceMap& map) {
    OverloadTies check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
