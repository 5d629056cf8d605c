// See int_literal_folding.h.
#include "rewrite/int_literal_folding.h"

#include <cctype>
#include <climits>
#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <string>

namespace fxport::xlate {

namespace {

// An unsuffixed decimal or hexadecimal literal as fxc reads it: the int of its low 32 bits.
std::optional<double> intLiteral(const Token& t) {
    if (t.kind != Token::Kind::Number) return std::nullopt;
    const std::string& s = t.text;
    const bool hex = s.size() > 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X');
    for (size_t i = hex ? 2 : 0; i < s.size(); ++i)
        if (!(hex ? std::isxdigit(static_cast<unsigned char>(s[i])) : std::isdigit(static_cast<unsigned char>(s[i])))) return std::nullopt;
    if (s.size() > (hex ? 18u : 19u)) return std::nullopt;  // beyond 64 bits: left to glslang
    const std::uint64_t v = std::strtoull(s.c_str(), nullptr, hex ? 16 : 10);
    return double(std::int32_t(std::uint32_t(v)));
}

bool isOperand(const Token& t) {
    return intLiteral(t) || t.is("+") || t.is("-") || t.is("*") || t.is("/") || t.is("%") || t.is("(") || t.is(")");
}

// Evaluates tokens [at, end) exactly (in double, as fxc), noting whether a step left int's range.
class Folder {
public:
    Folder(const std::vector<Token>& t, size_t at, size_t end) : t_(t), at_(at), end_(end) {}

    std::optional<double> whole() {
        auto v = sum();
        if (!v || at_ != end_) return std::nullopt;
        return v;
    }
    bool overflowed = false;
    int operators = 0;

private:
    std::optional<double> note(double v) {
        if (v < double(INT_MIN) || v > double(INT_MAX)) overflowed = true;
        return v;
    }
    std::optional<double> primary() {
        if (at_ >= end_) return std::nullopt;
        if (t_[at_].is("(")) {
            ++at_;
            auto v = sum();
            if (!v || at_ >= end_ || !t_[at_].is(")")) return std::nullopt;
            ++at_;
            return v;
        }
        if (t_[at_].is("-") || t_[at_].is("+")) {
            const bool negate = t_[at_++].is("-");
            auto v = primary();
            if (!v) return std::nullopt;
            ++operators;
            return note(negate ? -*v : *v);
        }
        auto v = intLiteral(t_[at_]);
        if (v) ++at_;
        return v;
    }
    std::optional<double> product() {
        auto v = primary();
        while (v && at_ < end_ && (t_[at_].is("*") || t_[at_].is("/") || t_[at_].is("%"))) {
            const std::string op = t_[at_++].text;
            auto r = primary();
            if (!r || (op != "*" && *r == 0)) return std::nullopt;  // division by zero: fxc's error, glslang's too
            ++operators;
            v = note(op == "*" ? *v * *r : op == "/" ? std::trunc(*v / *r) : std::fmod(*v, *r));
        }
        return v;
    }
    std::optional<double> sum() {
        auto v = product();
        while (v && at_ < end_ && (t_[at_].is("+") || t_[at_].is("-"))) {
            const bool add = t_[at_++].is("+");
            auto r = product();
            if (!r) return std::nullopt;
            ++operators;
            v = note(add ? *v + *r : *v - *r);
        }
        return v;
    }

    const std::vector<Token>& t_;
    size_t at_, end_;
};

const std::set<std::string> kBefore = {"=", "(", ",", "return", "[", "{", "?", ":"};
const std::set<std::string> kAfter = {";", ")", ",", "]", "}", "?", ":"};

// x86's truncating conversion of a double to int: out of range is 0x80000000.
std::string spelledInt(double v) {
    if (v < double(INT_MIN) || v > double(INT_MAX)) return "(-2147483647 - 1)";
    const long long i = static_cast<long long>(v);
    return i < 0 ? "(" + std::to_string(i) + ")" : std::to_string(i);
}

}  // namespace

std::vector<TextEdit> overflowingIntFoldsAsFxc(const EffectSyntax& syntax) {
    std::vector<TextEdit> edits;
    const auto& t = syntax.tokens;
    for (size_t b = 1; b < t.size(); ++b) {
        if (t[b - 1].kind == Token::Kind::String || !kBefore.count(t[b - 1].text) || !isOperand(t[b])) continue;
        // The run of operand tokens whose parentheses stay balanced; it must end the operand.
        size_t e = b;
        int depth = 0;
        while (e < t.size() && isOperand(t[e])) {
            if (t[e].is("(")) ++depth;
            if (t[e].is(")") && --depth < 0) break;
            ++e;
        }
        if (depth != 0 && depth != -1) continue;
        if (e >= t.size() || t[e].kind == Token::Kind::String || !kAfter.count(t[e].text)) continue;
        Folder folder(t, b, e);
        auto v = folder.whole();
        if (!v || folder.operators == 0 || !folder.overflowed) {
            b = e - 1 > b ? e - 1 : b;
            continue;
        }
        // Keep the run's line count: the lines after it keep their numbers.
        std::string spelled = spelledInt(*v);
        for (int l = t[b].line; l < t[e - 1].line; ++l) spelled += "\n";
        edits.push_back({t[b].offset, t[e - 1].end, spelled});
        b = e - 1;
    }
    return edits;
}

}  // namespace fxport::xlate
