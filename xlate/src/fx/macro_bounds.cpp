#include "fx/macro_bounds.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "fx/input_limits.h"

namespace fxport::xlate {

namespace {

struct Token {
    std::string text;
    int line = 0, column = 0;
};

struct LogicalLine {
    std::vector<Token> tokens;
    bool directive = false;  // begins with '#'
};

bool identStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool identChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// The file as logical lines of tokens (continuations joined, comments dropped, a string literal
// one token). Enough to find #define bodies and the names used; glslang judges the rest.
std::vector<LogicalLine> tokenize(std::string_view t) {
    std::vector<LogicalLine> lines(1);
    int line = 1;
    size_t lineStart = 0;
    bool inBlockComment = false;
    for (size_t i = 0; i < t.size();) {
        char c = t[i];
        if (inBlockComment) {
            if (c == '*' && i + 1 < t.size() && t[i + 1] == '/') inBlockComment = false, i += 2;
            else {
                if (c == '\n') ++line, lineStart = i + 1;
                ++i;
            }
            continue;
        }
        if (c == '\\' && i + 1 < t.size() && (t[i + 1] == '\n' || (t[i + 1] == '\r' && i + 2 < t.size() && t[i + 2] == '\n'))) {
            i += t[i + 1] == '\n' ? 2 : 3;
            ++line, lineStart = i;
            continue;
        }
        if (c == '\n') {
            lines.emplace_back();
            ++line, lineStart = ++i;
            continue;
        }
        if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v') {
            ++i;
            continue;
        }
        if (c == '/' && i + 1 < t.size() && t[i + 1] == '/') {
            while (i < t.size() && t[i] != '\n') ++i;
            continue;
        }
        if (c == '/' && i + 1 < t.size() && t[i + 1] == '*') {
            inBlockComment = true, i += 2;
            continue;
        }
        size_t start = i;
        if (identStart(c)) {
            while (i < t.size() && identChar(t[i])) ++i;
        } else if (c == '"') {
            for (++i; i < t.size() && t[i] != '"' && t[i] != '\n'; ++i)
                if (t[i] == '\\') ++i;
            if (i < t.size() && t[i] == '"') ++i;
        } else {
            ++i;
        }
        LogicalLine& l = lines.back();
        if (l.tokens.empty() && c == '#') l.directive = true;
        l.tokens.push_back({std::string(t.substr(start, std::min(i, t.size()) - start)), line, static_cast<int>(start - lineStart) + 1});
    }
    return lines;
}

unsigned long long saturatingAdd(unsigned long long a, unsigned long long b) {
    unsigned long long s;
    return __builtin_add_overflow(a, b, &s) ? ~0ull : s;
}

unsigned long long saturatingMul(unsigned long long a, unsigned long long b) {
    unsigned long long s;
    return __builtin_mul_overflow(a, b, &s) ? ~0ull : s;
}

constexpr const char* kParam = "\x01";  // a parameter occurrence in a function-like macro's body
constexpr unsigned long long kCap = static_cast<unsigned long long>(limits::kMaxPreprocessedBytes) + 1;

// For each "(" of `tokens`, the index of the ")" that closes it (tokens.size() when none does), found
// once: scanning forward at every call made nested calls cost depth x length, repeated per call (a
// 46 KB file of 250-deep calls took 3 s; fuzzer, device run of session 17).
std::vector<size_t> closingParens(const std::vector<std::string>& tokens) {
    std::vector<size_t> close(tokens.size(), tokens.size());
    std::vector<size_t> open;
    for (size_t i = 0; i < tokens.size(); ++i) {
        if (tokens[i] == "(") {
            open.push_back(i);
        } else if (tokens[i] == ")" && !open.empty()) {
            close[open.back()] = i;
            open.pop_back();
        }
    }
    return close;
}

}  // namespace

// The bytes `tokens[begin, end)` expand to at most, as a Cost: bytes outside parameters, and how
// many parameter occurrences (of a function-like macro's body) they hold.
MacroBounds::Cost MacroBounds::sequence(const Tokens& tokens, size_t begin, size_t end, Walk& walk) const {
    Cost total;
    for (size_t i = begin; i < end && !walk.tooDeep; ++i) {
        const std::string& tok = tokens.text[i];
        if (tok == kParam) {
            total.params = saturatingAdd(total.params, 1);
            continue;
        }
        auto it = macros_.find(tok);
        if (it == macros_.end() || walk.open.count(tok)) {  // not a macro, or inside its own expansion
            total.bytes = saturatingAdd(total.bytes, tok.size() + 1);
            continue;
        }
        Cost body = expansion(it->first, it->second, walk);
        if (!it->second.function) {
            total.bytes = saturatingAdd(total.bytes, body.bytes);
            continue;
        }
        // A call: the body, with each parameter occurrence replaced by (at most) all the arguments.
        if (i + 1 >= end || tokens.text[i + 1] != "(") {  // the name alone is no call
            total.bytes = saturatingAdd(total.bytes, tok.size() + 1);
            continue;
        }
        size_t close = std::min(tokens.close[i + 1], end);
        if (++walk.callNesting > kMaxCallNesting) walk.tooDeep = walk.callsTooDeep = true;
        Cost args = sequence(tokens, i + 2, close, walk);
        --walk.callNesting;
        total.bytes = saturatingAdd(total.bytes, saturatingAdd(body.bytes, saturatingMul(body.params, args.bytes)));
        total.params = saturatingAdd(total.params, saturatingMul(body.params, args.params));
        i = close;
    }
    total.bytes = std::min(total.bytes, kCap);
    return total;
}

MacroBounds::Cost MacroBounds::expansion(const std::string& name, const Macro& macro, Walk& walk) const {
    if (auto m = walk.memo.find(name); m != walk.memo.end()) return m->second;
    if (walk.open.size() >= kMaxDepth) {
        walk.tooDeep = true;
        return {};
    }
    walk.open.insert(name);
    int outerCalls = walk.callNesting;  // a body's calls nest from its own start
    walk.callNesting = 0;
    Cost largest;
    for (const auto& body : macro.bodies) {
        Cost c = sequence(body, 0, body.text.size(), walk);
        largest.bytes = std::max(largest.bytes, c.bytes);
        largest.params = std::max(largest.params, c.params);
    }
    walk.open.erase(name);
    walk.callNesting = outerCalls;
    walk.memo[name] = largest;
    return largest;
}

std::optional<Diagnostic> MacroBounds::addFile(std::string_view text, const std::string& displayPath) {
    std::vector<LogicalLine> lines = tokenize(text);
    Tokens used;  // the file outside #define lines, as one sequence
    std::vector<const Token*> where;
    for (const auto& l : lines) {
        const auto& t = l.tokens;
        if (l.directive && t.size() >= 3 && t[1].text == "define" && identStart(t[2].text[0])) {
            Macro& macro = macros_[t[2].text];
            size_t bodyStart = 3;
            std::set<std::string> params;
            // `NAME(` with no space: a function-like macro.
            if (t.size() > 3 && t[3].text == "(" && t[3].line == t[2].line && t[3].column == t[2].column + static_cast<int>(t[2].text.size())) {
                macro.function = true;
                for (bodyStart = 4; bodyStart < t.size() && t[bodyStart].text != ")"; ++bodyStart) params.insert(t[bodyStart].text);
                ++bodyStart;
            }
            Tokens body;
            for (size_t i = bodyStart; i < t.size(); ++i) body.text.push_back(params.count(t[i].text) ? std::string(kParam) : t[i].text);
            body.close = closingParens(body.text);
            macro.bodies.push_back(std::move(body));
            continue;
        }
        if (l.directive && t.size() >= 2 && (t[1].text == "undef" || t[1].text == "include" || t[1].text == "pragma" || t[1].text == "line")) continue;
        for (size_t i = l.directive ? 1 : 0; i < t.size(); ++i) {
            used.text.push_back(t[i].text);
            where.push_back(&t[i]);
        }
    }
    used.close = closingParens(used.text);
    Walk walk;
    auto tooLarge = [&](const std::string& name, SourceLocation at, std::string sourceLine) {
        Diagnostic d;
        d.id = diag::kMacroLimit;
        d.message = walk.callsTooDeep ? "macro calls nested more than " + std::to_string(kMaxCallNesting) + " deep in the arguments of '" + name +
                                            "', the most fxport preprocesses"
                  : walk.tooDeep ? "macro '" + name + "' expands through more than " + std::to_string(kMaxDepth) +
                                       " nested macros, the most fxport preprocesses"
                                 : "macro '" + name + "' expands to more than " + std::to_string(limits::kMaxPreprocessedBytes >> 20) +
                                       " MiB of text (its definitions nest macros that repeat others), the most fxport preprocesses";
        d.location = std::move(at);
        d.sourceLine = std::move(sourceLine);
        return d;
    };
    // The names earlier files used, with this file's definitions now known (an include may define
    // what the effect uses after it). Names only: calls with their arguments were bounded where
    // they are, with the definitions known then. Within a budget, past which the worker's limits
    // remain the bound.
    if (recheckBudget_ > 0)
        for (const auto& [name, at] : usedNames_) {
            if (--recheckBudget_ <= 0) break;
            if (!macros_.count(name)) continue;
            Cost c = sequence(Tokens{{name}, {1}}, 0, 1, walk);
            if (c.bytes > limits::kMaxPreprocessedBytes || walk.tooDeep) return tooLarge(name, at, {});
        }
    for (size_t i = 0; i < used.text.size(); ++i)
        if (identStart(used.text[i][0]) && !usedNames_.count(used.text[i]))
            usedNames_.emplace(used.text[i], SourceLocation{displayPath, where[i]->line, where[i]->column});
    // Each use (a call with its arguments, which bounds the macros inside them too).
    for (size_t i = 0; i < used.text.size(); ++i) {
        auto macro = macros_.find(used.text[i]);
        if (macro == macros_.end()) continue;
        size_t end = i + 1;
        if (end < used.text.size() && used.text[end] == "(" && macro->second.function) end = used.close[end];
        end = std::min(end + 1, used.text.size());
        Cost c = sequence(used, i, end, walk);
        if (c.bytes > limits::kMaxPreprocessedBytes || walk.tooDeep)
            return tooLarge(used.text[i], {displayPath, where[i]->line, where[i]->column}, lineOf(text, where[i]->line));
        i = end - 1;
    }
    return std::nullopt;
}

}  // namespace fxport::xlate
