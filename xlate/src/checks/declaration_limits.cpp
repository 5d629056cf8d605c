// Limits fxc puts on what a declaration or a loop may ask for, where glslang takes anything:
//  - an array dimension must be between 1 and 65536 (`float a[65537];`: fxc X3059; vkd3d's
//    invalid pins it); judged where the dimension is a literal, and reported as the element limit
//    (FX1204, docs/limits.md) at the dimension, where fxc reports it (a typedef's, not the variable's);
//  - `[unroll]` without a count on a loop that runs 1024 times or more: fxc gives up unrolling
//    after 1024 iterations and refuses the loop (X3511 "loop does not appear to terminate in a
//    timely manner (1024 iterations)"; vkd3d's unroll). Judged on `for (i = A; i < B; ++i)` with
//    literal bounds (`<`, `<=`, `i++`, `++i`, `i += 1`).
#include <cstdlib>

#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

constexpr long kMaxArrayDimension = 65536;
constexpr long kUnrollLimit = 1024;

bool integerLiteral(const Token& t, long& value) {
    if (t.kind != Token::Kind::Number || t.text.find_first_of(".eEfFhH") != std::string::npos) return false;
    char* end = nullptr;
    value = std::strtol(t.text.c_str(), &end, 0);
    return end != t.text.c_str();
}

class DeclarationLimits : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (size_t i = 2; i + 2 < t_.size(); ++i) {
            long n = 0;
            // `Type name[N]`: a name after a type name, then the dimension.
            if (t_[i].is("[") && t_[i - 1].isIdent() && t_[i - 2].isIdent() && !t_[i - 2].is("return") && !t_[i - 2].is("else") && integerLiteral(t_[i + 1], n) &&
                t_[i + 2].is("]") && n > kMaxArrayDimension)
                report(diag::kArrayTooLarge, "array dimension " + t_[i + 1].text + " of '" + t_[i - 1].text + "' must be between 1 and 65536 (fxc X3059)", i + 1);
            if (t_[i].is("unroll") && t_[i - 1].is("[") && t_[i + 1].is("]")) unroll(i);
        }
    }

private:
    // `[unroll] for (i = A; i < B; ++i)` (also `int i = A`), at the attribute's name.
    void unroll(size_t at) {
        size_t k = at + 2;
        if (!tok(k).is("for") || !tok(k + 1).is("(")) return;
        k += 2;
        if (tok(k).isIdent() && tok(k + 1).isIdent() && tok(k + 2).is("=")) ++k;  // `int i = 0`
        long from = 0, to = 0;
        const std::string var = tok(k).text;
        if (!tok(k).isIdent() || !tok(k + 1).is("=") || !integerLiteral(tok(k + 2), from) || !tok(k + 3).is(";")) return;
        k += 4;
        if (!tok(k).is(var) || !tok(k + 1).is("<")) return;
        const bool inclusive = tok(k + 2).is("=") && tok(k + 1).end == tok(k + 2).offset;  // `<=` is two tokens
        k += inclusive ? 3 : 2;
        if (!integerLiteral(tok(k), to) || !tok(k + 1).is(";")) return;
        k += 2;
        const bool step = (tok(k).is("++") && tok(k + 1).is(var) && tok(k + 2).is(")")) || (tok(k).is(var) && tok(k + 1).is("++") && tok(k + 2).is(")")) ||
                          (tok(k).is(var) && tok(k + 1).is("+=") && tok(k + 2).is("1") && tok(k + 3).is(")"));
        const long iterations = to - from + (inclusive ? 1 : 0);
        if (step && iterations >= kUnrollLimit)
            report("unable to unroll loop, loop does not appear to terminate in a timely manner (" + std::to_string(kUnrollLimit) +
                       " iterations); this loop runs " + std::to_string(iterations) + " times (fxc X3511)",
                   at);
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findDeclarationLimitErrors(const EffectSyntax& syntax, const SourceMap& map) {
    DeclarationLimits check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
