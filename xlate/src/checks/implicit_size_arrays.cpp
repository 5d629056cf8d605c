// fxc's rules for arrays declared without a size (`float4 a[] = {...}`, vkd3d's
// initializer-implicit-array pins them), which glslang does not check:
//  - the size comes from an initializer: a declaration without one is an error, and so is an
//    unsized member of a struct or an unsized typedef;
//  - the initializer's components fill whole elements: 7 numbers cannot make float4s.
// Only initializers of plain numbers are counted; others (vectors, calls) are left to glslang.
#include <algorithm>
#include <cstdlib>

#include "checks/fxc_checks.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

class ImplicitSizeArrays : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        std::vector<std::pair<size_t, size_t>> structBodies;  // `struct S { ... }` braces
        for (size_t i = 0; i + 2 < t_.size(); ++i)
            if (t_[i].is("struct")) {
                size_t b = t_[i + 1].is("{") ? i + 1 : t_[i + 2].is("{") && t_[i + 1].isIdent() ? i + 2 : 0;
                if (b) structBodies.push_back({b, closing(b)});
            }
        for (size_t i = 2; i + 1 < t_.size(); ++i) {
            if (!t_[i].is("[") || !t_[i + 1].is("]") || !t_[i - 1].isIdent()) continue;
            const Token& before = t_[i - 2];
            if (!(before.isIdent() || before.is(">"))) continue;  // `Type name[]`, not `a[]` in an expression
            if (inParameters(i)) continue;
            bool inStruct = false;
            for (auto [b, e] : structBodies) inStruct |= i > b && i < e;
            size_t start = statementStart(i - 1), after = i + 2;
            long long inner = 1;  // `float2 a[][3]`: the other dimensions' product (capped: source numbers)
            while (t_[after].is("[")) {
                size_t close = closing(after);
                const long long n = close == after + 2 && t_[after + 1].kind == Token::Kind::Number
                                        ? std::clamp(std::strtoll(t_[after + 1].text.c_str(), nullptr, 10), 1LL, 1LL << 20) : 0;
                inner = std::min(inner * n, 1LL << 20);
                after = close + 1;
            }
            if (inStruct) report("struct member '" + t_[i - 1].text + "' is an array without a size: fxc needs its size", i - 1);
            else if (t_[start].is("typedef")) report("typedef '" + t_[i - 1].text + "' is an array without a size: fxc needs its size", i - 1);
            else if (!t_[after].is("=")) report("array '" + t_[i - 1].text + "' has no size and no initializer to take it from", i - 1);
            else if (inner > 0) components(i - 1, typeBefore(i - 1), int(inner), after + 1);
        }
    }

private:
    // A function's parameter list contains `at` (parameters are not variables with initializers).
    bool inParameters(size_t at) const {
        const FxFunction* f = functionAt(at);
        return f && at < f->body.begin;
    }
    size_t statementStart(size_t at) const {
        size_t i = at;
        while (i > 0 && !(t_[i - 1].is(";") || t_[i - 1].is("{") || t_[i - 1].is("}"))) --i;
        return i;
    }
    // The element type of `name` at `nameToken` (the token before it; `struct S` too).
    std::string typeBefore(size_t nameToken) const { return t_[nameToken - 1].text; }

    void components(size_t nameToken, const std::string& typeName, int inner, size_t value) {
        BasicType b = describeBasicType(syntax_.resolveType(typeName));
        if (!b.ok || !t_[value].is("{")) return;
        size_t end = closing(value);
        int numbers = 0;
        for (size_t k = value + 1; k < end; ++k) {
            const Token& x = t_[k];
            if (x.is("{") || x.is("}") || x.is(",") || x.is("-") || x.is("+")) continue;
            if (x.kind != Token::Kind::Number && !x.is("true") && !x.is("false")) return;  // not plain numbers: not judged
            ++numbers;
        }
        int per = b.rows * b.columns * inner;
        if (numbers % per != 0)
            report("array '" + t_[nameToken].text + "' without a size gets " + std::to_string(numbers) + " components, not a whole number of " +
                       (inner > 1 ? "elements" : typeName + "s") + " (" + std::to_string(per) + " each)",
                   nameToken);
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findImplicitSizeArrayErrors(const EffectSyntax& syntax, const SourceMap& map) {
    ImplicitSizeArrays check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
