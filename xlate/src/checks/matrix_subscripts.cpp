// A matrix swizzle mixing zero-based and one-based subscripts (`mat._11_m00`): fxc refuses it
// (X3018 invalid subscript; vkd3d's swizzle-matrix pins it), glslang took the swizzle.
// Judged on the name after `.` alone: every piece is `_mRC` (0-3) or `_RC` (1-4) and both kinds
// occur; a struct member spelled so is no HLSL anyone writes.
#include <string>

#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

// Counts the zero-based and one-based pieces of `s`; false when `s` is not a matrix swizzle.
bool matrixSwizzle(const std::string& s, int& zeroBased, int& oneBased) {
    size_t at = 0;
    while (at < s.size()) {
        if (s[at] != '_') return false;
        const bool zero = at + 1 < s.size() && s[at + 1] == 'm';
        const size_t digits = at + (zero ? 2 : 1);
        if (digits + 2 > s.size()) return false;
        const char lo = zero ? '0' : '1', hi = zero ? '3' : '4';
        for (size_t k = digits; k < digits + 2; ++k)
            if (s[k] < lo || s[k] > hi) return false;
        (zero ? zeroBased : oneBased) += 1;
        at = digits + 2;
    }
    return at > 0;
}

class MatrixSubscripts : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (size_t i = 1; i < t_.size(); ++i) {
            if (!t_[i].isIdent() || !t_[i - 1].is(".") || !inFunction(i)) continue;
            int zeroBased = 0, oneBased = 0;
            if (matrixSwizzle(t_[i].text, zeroBased, oneBased) && zeroBased && oneBased)
                report("invalid subscript '" + t_[i].text + "': a swizzle takes zero-based (_m00) or one-based (_11) subscripts, not both (fxc X3018)", i);
        }
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findMatrixSubscriptErrors(const EffectSyntax& syntax, const SourceMap& map) {
    MatrixSubscripts check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
