// countTextureFetches: a small statement parser over GLSL tokens that adds up sampling calls, with
// constant-trip loops multiplied out and branches kept as a least..most range.
#include "fxport/xlate/texture_fetches.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <optional>
#include <set>
#include <vector>

namespace fxport::xlate {

std::string TextureFetches::text() const {
    if (unbounded) return ">=" + std::to_string(least);
    if (least == most) return std::to_string(least);
    return std::to_string(least) + ".." + std::to_string(most);
}

namespace {

// Far past any real shader, so that a multiplied-out count cannot overflow.
constexpr long kCap = 1L << 30;

struct Range {
    long least = 0, most = 0;
    bool unbounded = false;
    bool returns = false;  // a `return` inside (code after it may not run)
    bool breaks = false;   // a `break` or `continue` not inside a nested loop or switch

    Range& operator+=(const Range& r) {
        least = std::min(kCap, least + r.least);
        most = std::min(kCap, most + r.most);
        unbounded = unbounded || r.unbounded;
        returns = returns || r.returns;
        breaks = breaks || r.breaks;
        return *this;
    }
    // Only one of two ways runs.
    static Range either(const Range& a, const Range& b) {
        Range r;
        r.least = std::min(a.least, b.least);
        r.most = std::max(a.most, b.most);
        r.unbounded = a.unbounded || b.unbounded;
        r.returns = a.returns || b.returns;
        r.breaks = a.breaks || b.breaks;
        return r;
    }
    // May not run at all.
    Range maybe() const { return either(*this, Range{}); }
};

bool isSamplingCall(const std::string& name) {
    static const std::set<std::string> queries = {"textureSize", "textureQueryLod", "textureQueryLevels", "textureSamples"};
    if (queries.count(name)) return false;
    return name.rfind("texture", 0) == 0 || name.rfind("texelFetch", 0) == 0;
}

std::vector<std::string> tokenize(const std::string& s) {
    std::vector<std::string> out;
    static const char* twoChar[] = {"<=", ">=", "==", "!=", "++", "--", "+=", "-=", "*=", "/=", "&&", "||", "<<", ">>"};
    std::size_t i = 0;
    while (i < s.size()) {
        const char c = s[i];
        if (std::isspace(static_cast<unsigned char>(c))) {
            ++i;
        } else if (c == '/' && i + 1 < s.size() && s[i + 1] == '/') {
            i = s.find('\n', i);
            if (i == std::string::npos) break;
        } else if (c == '/' && i + 1 < s.size() && s[i + 1] == '*') {
            i = s.find("*/", i + 2);
            if (i == std::string::npos) break;
            i += 2;
        } else if (c == '#') {  // preprocessor line (#version, #extension)
            i = s.find('\n', i);
            if (i == std::string::npos) break;
        } else if (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.') {
            std::size_t j = i;
            // Identifiers, and numbers with their exponent sign (1.5e-3).
            while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_' || s[j] == '.' ||
                                    ((s[j] == '-' || s[j] == '+') && j > i && (s[j - 1] == 'e' || s[j - 1] == 'E') &&
                                     std::isdigit(static_cast<unsigned char>(s[i])))))
                ++j;
            out.push_back(s.substr(i, j - i));
            i = j;
        } else {
            std::string op(1, c);
            for (const char* two : twoChar)
                if (s.compare(i, 2, two) == 0) op = two;
            out.push_back(op);
            i += op.size();
        }
    }
    return out;
}

bool isIdentifier(const std::string& t) {
    return !t.empty() && (std::isalpha(static_cast<unsigned char>(t[0])) || t[0] == '_');
}

std::optional<long> integerLiteral(const std::vector<std::string>& t, std::size_t& i, std::size_t end) {
    bool negative = false;
    if (i < end && t[i] == "-") negative = true, ++i;
    if (i >= end || t[i].empty() || !std::isdigit(static_cast<unsigned char>(t[i][0]))) return std::nullopt;
    std::string digits = t[i];
    if (!digits.empty() && (digits.back() == 'u' || digits.back() == 'U')) digits.pop_back();
    for (char c : digits)
        if (!std::isdigit(static_cast<unsigned char>(c))) return std::nullopt;
    if (digits.size() > 9) return std::nullopt;
    ++i;
    const long v = std::stol(digits);
    return negative ? -v : v;
}

class Counter {
public:
    explicit Counter(std::vector<std::string> tokens) : t_(std::move(tokens)) { findFunctions(); }

    TextureFetches countMain() {
        Range r = function("main");
        TextureFetches out;
        out.least = int(r.least);
        out.most = int(r.most);
        out.unbounded = r.unbounded;
        return out;
    }

private:
    std::vector<std::string> t_;
    std::map<std::string, std::pair<std::size_t, std::size_t>> functions_;  // name -> body [begin, end)
    std::map<std::string, Range> counted_;
    std::set<std::string> counting_;  // recursion guard (GLSL forbids recursion; the text may still have it)

    std::size_t matching(std::size_t open) const {
        const std::string& o = t_[open];
        const std::string c = o == "(" ? ")" : o == "{" ? "}" : "]";
        int depth = 0;
        for (std::size_t i = open; i < t_.size(); ++i) {
            if (t_[i] == o) ++depth;
            else if (t_[i] == c && --depth == 0) return i;
        }
        return t_.size();
    }

    // Function definitions at file scope: NAME ( ... ) { body }.
    void findFunctions() {
        for (std::size_t i = 0; i < t_.size(); ++i) {
            if (t_[i] == "{") {  // a block at file scope (uniform block, struct): skip it
                i = matching(i);
                continue;
            }
            if (!isIdentifier(t_[i]) || i + 1 >= t_.size() || t_[i + 1] != "(") continue;
            const std::size_t close = matching(i + 1);
            if (close + 1 < t_.size() && t_[close + 1] == "{") {
                const std::size_t end = matching(close + 1);
                functions_[t_[i]] = {close + 2, end};
                i = end;
            } else {
                i = close;
            }
        }
    }

    Range function(const std::string& name) {
        if (auto found = counted_.find(name); found != counted_.end()) return found->second;
        auto body = functions_.find(name);
        if (body == functions_.end() || counting_.count(name)) return {};
        counting_.insert(name);
        Range r = block(body->second.first, body->second.second);
        counting_.erase(name);
        r.returns = r.breaks = false;  // the caller goes on after the call
        counted_[name] = r;
        return r;
    }

    // Tokens [i, end) as an expression: sampling calls and calls of the shader's own functions.
    Range expression(std::size_t i, std::size_t end) {
        Range r;
        bool conditional = false;  // after ?, && or ||: may not be evaluated
        for (; i < end; ++i) {
            const std::string& tok = t_[i];
            if (tok == "?" || tok == "&&" || tok == "||") conditional = true;
            if (!isIdentifier(tok) || i + 1 >= end || t_[i + 1] != "(") continue;
            Range call;
            // The shader's own functions first: HLSL code may name one textureSomething.
            if (functions_.count(tok)) call = function(tok);
            else if (isSamplingCall(tok)) call.least = call.most = 1;
            r += conditional ? call.maybe() : call;
        }
        return r;
    }

    // Statements in [i, end).
    Range block(std::size_t i, std::size_t end) {
        Range r;
        while (i < end) {
            Range s = statement(i, end);
            // After a statement that may return, break or continue, the rest may not run.
            r += r.returns || r.breaks ? s.maybe() : s;
        }
        return r;
    }

    std::size_t statementEnd(std::size_t i, std::size_t end) const {
        int depth = 0;
        for (; i < end; ++i) {
            if (t_[i] == "(" || t_[i] == "[" || t_[i] == "{") ++depth;
            else if (t_[i] == ")" || t_[i] == "]" || t_[i] == "}") --depth;
            else if (t_[i] == ";" && depth == 0) return i;
        }
        return end;
    }

    // One statement starting at i; moves i past it.
    Range statement(std::size_t& i, std::size_t end) {
        const std::string& tok = t_[i];
        if (tok == "{") {
            const std::size_t close = std::min(matching(i), end);
            Range r = block(i + 1, close);
            i = close + 1;
            return r;
        }
        if (tok == "if" && i + 1 < end && t_[i + 1] == "(") {
            const std::size_t close = matching(i + 1);
            Range r = expression(i + 2, close);
            i = close + 1;
            Range then = i < end ? statement(i, end) : Range{};
            Range otherwise;
            if (i < end && t_[i] == "else") {
                ++i;
                otherwise = i < end ? statement(i, end) : Range{};
            }
            r += Range::either(then, otherwise);
            return r;
        }
        if (tok == "for" && i + 1 < end && t_[i + 1] == "(") return forLoop(i, end);
        if (tok == "while" && i + 1 < end && t_[i + 1] == "(") {
            const std::size_t close = matching(i + 1);
            Range condition = expression(i + 2, close);
            i = close + 1;
            Range body = i < end ? statement(i, end) : Range{};
            return unknownLoop(condition, body, false);
        }
        if (tok == "do") {
            ++i;
            Range body = i < end ? statement(i, end) : Range{};
            Range condition;
            bool once = false;  // do { ... } while (false): SPIRV-Cross's block to break out of
            if (i + 1 < end && t_[i] == "while" && t_[i + 1] == "(") {
                const std::size_t close = matching(i + 1);
                condition = expression(i + 2, close);
                once = close == i + 3 && t_[i + 2] == "false";
                i = close + 1;
            }
            if (i < end && t_[i] == ";") ++i;
            if (once) {
                body.breaks = false;
                return body;
            }
            return unknownLoop(condition, body, true);
        }
        if (tok == "switch" && i + 1 < end && t_[i + 1] == "(") {
            const std::size_t close = matching(i + 1);
            Range r = expression(i + 2, close);
            i = close + 1;
            if (i < end && t_[i] == "{") {
                const std::size_t bodyEnd = std::min(matching(i), end);
                Range body = block(i + 1, bodyEnd);
                body.breaks = false;
                r += body.maybe();  // which cases run depends on the value
                i = bodyEnd + 1;
            }
            return r;
        }
        if ((tok == "case" || tok == "default")) {
            while (i < end && t_[i] != ":") ++i;
            ++i;
            return {};
        }
        const std::size_t semicolon = statementEnd(i, end);
        Range r = expression(i, semicolon);
        if (tok == "return") r.returns = true;
        if (tok == "break" || tok == "continue") r.breaks = true;
        i = semicolon + 1;
        return r;
    }

    // A loop whose trip count the text does not fix: the body may run any number of times.
    static Range unknownLoop(const Range& condition, const Range& body, bool runsOnce) {
        Range r = condition;  // evaluated at least once
        if (runsOnce) r += body;
        if (body.most > 0 || body.unbounded || condition.most > 0 || condition.unbounded) r.unbounded = true;
        r.returns = r.returns || body.returns;
        r.breaks = false;
        return r;
    }

    // Where `name` is assigned in [i, end): each position of the assignment's first token.
    std::vector<std::size_t> assignments(const std::string& name, std::size_t i, std::size_t end) const {
        std::vector<std::size_t> at;
        static const std::set<std::string> assigning = {"=", "++", "--", "+=", "-=", "*=", "/="};
        for (; i < end; ++i) {
            if (t_[i] != name) continue;
            if (i + 1 < end && assigning.count(t_[i + 1])) at.push_back(i);
            else if (i > 0 && (t_[i - 1] == "++" || t_[i - 1] == "--")) at.push_back(i - 1);
        }
        return at;
    }

    // The step of `name` in tokens [i, end) when they are exactly one increment: NAME++, ++NAME,
    // NAME--, --NAME, NAME += LIT, NAME -= LIT.
    std::optional<long> step(const std::string& name, std::size_t i, std::size_t end) const {
        const std::size_t n = end - i;
        if (n == 2 && t_[i] == name && t_[i + 1] == "++") return 1;
        if (n == 2 && t_[i] == "++" && t_[i + 1] == name) return 1;
        if (n == 2 && t_[i] == name && t_[i + 1] == "--") return -1;
        if (n == 2 && t_[i] == "--" && t_[i + 1] == name) return -1;
        if (n >= 3 && t_[i] == name && (t_[i + 1] == "+=" || t_[i + 1] == "-=")) {
            std::size_t k = i + 2;
            std::optional<long> v = integerLiteral(t_, k, end);
            if (!v || k != end) return std::nullopt;
            return t_[i + 1] == "+=" ? *v : -*v;
        }
        return std::nullopt;
    }

    static std::optional<long> tripCount(long start, const std::string& op, long limit, long step) {
        if (step == 0) return std::nullopt;
        auto ceilDiv = [](long a, long b) { return (a + b - 1) / b; };
        if (op == "<" && step > 0) return limit > start ? ceilDiv(limit - start, step) : 0;
        if (op == "<=" && step > 0) return limit >= start ? (limit - start) / step + 1 : 0;
        if (op == ">" && step < 0) return start > limit ? ceilDiv(start - limit, -step) : 0;
        if (op == ">=" && step < 0) return start >= limit ? (start - limit) / -step + 1 : 0;
        if (op == "!=" && (limit - start) % step == 0 && (limit - start) / step >= 0) return (limit - start) / step;
        return std::nullopt;
    }

    Range forLoop(std::size_t& i, std::size_t end) {
        const std::size_t open = i + 1, close = matching(open);
        const std::size_t semi1 = statementEnd(open + 1, close), semi2 = statementEnd(semi1 + 1, close);
        Range init = expression(open + 1, semi1), condition = expression(semi1 + 1, semi2),
              increment = expression(semi2 + 1, close);
        i = close + 1;
        const std::size_t bodyBegin = i;
        Range body = i < end ? statement(i, end) : Range{};
        const std::size_t bodyEnd = i;

        // for ([int|uint] NAME = LIT; NAME OP LIT; STEP[, other increments])
        std::optional<long> trips;
        std::size_t k = open + 1;
        if (k < semi1 && (t_[k] == "int" || t_[k] == "uint")) ++k;
        const std::string name = k < semi1 ? t_[k] : "";
        std::optional<long> start, limit;
        long stepBy = 0;  // 0: not found
        if (isIdentifier(name) && k + 1 < semi1 && t_[k + 1] == "=") {
            std::size_t v = k + 2;
            start = integerLiteral(t_, v, semi1);
            if (v != semi1) start.reset();
        }
        std::string op;
        if (start && semi1 + 3 <= semi2 && t_[semi1 + 1] == name) {
            op = t_[semi1 + 2];
            std::size_t v = semi1 + 3;
            limit = integerLiteral(t_, v, semi2);
            if (v != semi2) limit.reset();
        }
        bool trailingContinue = false;  // SPIRV-Cross's `NAME++; continue; }` at the body's end
        if (limit) {
            // The step: one comma-separated increment, or the body's last statement.
            std::size_t from = semi2 + 1;
            for (std::size_t j = semi2 + 1; j <= close; ++j) {
                if (j < close && t_[j] != ",") continue;
                if (auto s = step(name, from, j)) stepBy = *s;
                from = j + 1;
            }
            std::vector<std::size_t> inBody = assignments(name, bodyBegin, bodyEnd);
            if (stepBy && !inBody.empty()) stepBy = 0;
            if (!stepBy && inBody.size() == 1 && t_[bodyBegin] == "{") {
                // { ... NAME++; [continue;] }
                std::size_t last = bodyEnd - 1;  // the closing brace
                if (last >= 2 && t_[last - 1] == ";" && t_[last - 2] == "continue") last -= 2, trailingContinue = true;
                const std::size_t stepBegin = inBody[0];
                if (last >= 1 && t_[last - 1] == ";" && stepBegin < last - 1) {
                    stepBy = step(name, stepBegin, last - 1).value_or(0);
                    // Any other break or continue could skip the step.
                    if (stepBy && stepBegin > bodyBegin && t_[stepBegin - 1] != ";" && t_[stepBegin - 1] != "{" &&
                        t_[stepBegin - 1] != "}")
                        stepBy = 0;
                }
            }
        }
        if (start && limit && stepBy) trips = tripCount(*start, op, *limit, stepBy);
        if (trailingContinue && trips) {
            // The trailing continue is the loop's own; only another break/continue counts.
            int others = 0;
            for (std::size_t j = bodyBegin; j < bodyEnd; ++j)
                if (t_[j] == "break" || t_[j] == "continue") ++others;
            if (others == 1) body.breaks = false;
        }

        Range r = init;
        if (!trips || *trips > kCap) {
            r += unknownLoop(condition, body, false);
            return r;
        }
        const long n = *trips;
        Range each = body;
        each += increment;
        auto times = [](long count, long per) { return long(std::min(double(kCap), double(count) * double(per))); };
        Range loop;
        loop.least = each.breaks || each.returns ? 0 : times(n, each.least);
        loop.most = times(n, each.most);
        loop.unbounded = each.unbounded;
        loop.returns = each.returns;
        Range conditions;  // evaluated n + 1 times
        conditions.least = times(n + 1, condition.least);
        conditions.most = times(n + 1, condition.most);
        conditions.unbounded = condition.unbounded;
        if (each.breaks || each.returns) conditions.least = condition.least;
        r += loop;
        r += conditions;
        return r;
    }
};

}  // namespace

TextureFetches countTextureFetches(const std::string& glsl) { return Counter(tokenize(glsl)).countMain(); }

}  // namespace fxport::xlate
