// fxc reads an integer literal without a suffix as an int whatever its value, so `3000000000` is
// a negative int to it; at SM 1-3, where integers are floats, it refuses to give a uint variable
// a constant that is negative as an int (vkd3d's sm1-const-folding: `uint x = 3000000000;` and
// `uint x = 3000000000 + 3000000000;` are refused there, `uint x = 3000000000u;` and
// `int x = 3000000000;` compile). glslang reads the literal as the uint it spells. Judged on a
// uint declaration whose value is integer literals and `+` alone (nothing fxc could fold
// differently), in the functions an SM 1-3 entry reaches; SM 4-5 wrap the value and compile.
#include <cctype>
#include <cstdlib>

#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

// A decimal integer literal without the u suffix, its value; -1 when `t` is no such literal. A
// hexadecimal one is not judged: `uint u = 0xfffffffe;` compiles at SM 1-3 (vkd3d's cast-to-int).
long long unsignedFreeValue(const Token& t) {
    if (t.kind != Token::Kind::Number) return -1;
    const std::string& s = t.text;
    if (s.size() > 1 && s[0] == '0') return -1;  // hexadecimal or octal
    for (char c : s)
        if (!std::isdigit(static_cast<unsigned char>(c))) return -1;
    if (s.size() > 18) return -1;  // far beyond 32 bits: not judged
    return std::strtoll(s.c_str(), nullptr, 10);
}

class NegativeUintConstants : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& e : compiledEntries()) {
            if (e.profile.major >= 4) continue;
            for (const FxFunction* f : reachableFrom(*e.function))
                for (size_t i = f->body.begin; i + 3 < f->body.end; ++i)
                    if (t_[i].is("uint") && t_[i + 1].isIdent() && t_[i + 2].is("=")) initializer(i + 3, f->body.end);
        }
    }

private:
    // The literal that is negative as an int, when the value from `begin` to its `;` or `,` is
    // literals and `+` alone.
    void initializer(size_t begin, size_t end) {
        size_t negative = 0;
        for (size_t i = begin; i < end; ++i) {
            if (t_[i].is(";") || t_[i].is(",")) break;
            const long long v = unsignedFreeValue(t_[i]);
            if (v < 0 && !t_[i].is("+")) return;
            if (v > 0x7FFFFFFFLL && !negative) negative = i;
        }
        if (negative)
            report("the literal " + t_[negative].text + " is a negative int to fxc, and a uint cannot take a negative constant at shader model 1-3 (write " +
                       t_[negative].text + "u)",
                   negative);
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findNegativeUintConstantErrors(const EffectSyntax& syntax, const SourceMap& map) {
    NegativeUintConstants check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
