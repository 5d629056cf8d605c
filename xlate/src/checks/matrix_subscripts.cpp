// Subscripts fxc refuses as invalid (X3018) and glslang takes:
//  - a matrix swizzle mixing zero-based and one-based subscripts (`mat._11_m00`; vkd3d's
//    swizzle-matrix pins it). Judged on the name after `.` alone: every piece is `_mRC` (0-3) or
//    `_RC` (1-4) and both kinds occur; a struct member spelled so is no HLSL anyone writes;
//  - a swizzle of GLSL's texture-coordinate set (`c.q`, `uv.st`): HLSL has xyzw and rgba only,
//    glslang's HLSL front end takes stpq too (and reads c.q as c.w). Judged on the name after `.`:
//    one to four of s, t, p, q, not followed by `(` and spelled unlike any member a struct of the
//    effect declares (`colours[0].q` of `struct { float p, q; }` is a member).
#include <set>
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
        const std::set<std::string> members = structMemberSpellings();
        for (size_t i = 1; i < t_.size(); ++i) {
            if (!t_[i].isIdent() || !t_[i - 1].is(".") || !inFunction(i)) continue;
            int zeroBased = 0, oneBased = 0;
            if (matrixSwizzle(t_[i].text, zeroBased, oneBased) && zeroBased && oneBased)
                report("invalid subscript '" + t_[i].text + "': a swizzle takes zero-based (_m00) or one-based (_11) subscripts, not both (fxc X3018)", i);
            if (textureCoordinateSwizzle(t_[i].text) && !members.count(t_[i].text) && !(i + 1 < t_.size() && t_[i + 1].is("(")))
                report("invalid subscript '" + t_[i].text + "': HLSL swizzles with x, y, z, w or r, g, b, a (s, t, p, q are GLSL's) (fxc X3018)", i);
        }
    }

private:
    static bool textureCoordinateSwizzle(const std::string& s) {
        return !s.empty() && s.size() <= 4 && s.find_first_not_of("stpq") == std::string::npos;
    }
    // Every identifier inside the braces of a `struct` definition (anywhere, local ones too): an
    // over-approximation of the member names, which only spares a spelling.
    std::set<std::string> structMemberSpellings() const {
        std::set<std::string> names;
        for (const auto& st : syntax_.structs)
            for (const auto& m : st.members) names.insert(m.name);
        for (size_t i = 0; i < t_.size(); ++i) {
            if (!t_[i].is("struct")) continue;
            size_t open = i + 1;
            while (open < t_.size() && !t_[open].is("{") && !t_[open].is(";") && !t_[open].is("(")) ++open;
            if (open >= t_.size() || !t_[open].is("{")) continue;
            int depth = 0;
            for (size_t k = open; k < t_.size(); ++k) {
                if (t_[k].is("{")) ++depth;
                if (t_[k].is("}") && --depth == 0) break;
                if (t_[k].isIdent()) names.insert(t_[k].text);
            }
        }
        return names;
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findMatrixSubscriptErrors(const EffectSyntax& syntax, const SourceMap& map) {
    MatrixSubscripts check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
