// See define_ternaries.h.
#include "fx/define_ternaries.h"

#include <cctype>
#include <optional>

namespace fxport::xlate {

namespace {

bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\r'; }
bool isWordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

size_t skipSpaces(const std::string& s, size_t i, size_t end) {
    while (i < end && isSpace(s[i])) ++i;
    return i;
}

// An integer literal (digits, then u/l suffixes), bare or in one pair of parentheses, at i: one
// past its end, or nullopt.
std::optional<size_t> integerOperand(const std::string& s, size_t i, size_t end) {
    i = skipSpaces(s, i, end);
    const bool parenthesised = i < end && s[i] == '(';
    if (parenthesised) i = skipSpaces(s, i + 1, end);
    if (i < end && s[i] == '-') ++i;
    const size_t digits = i;
    while (i < end && std::isdigit(static_cast<unsigned char>(s[i]))) ++i;
    if (i == digits) return std::nullopt;
    while (i < end && (s[i] == 'u' || s[i] == 'U' || s[i] == 'l' || s[i] == 'L')) ++i;
    if (i < end && isWordChar(s[i])) return std::nullopt;
    if (parenthesised) {
        i = skipSpaces(s, i, end);
        if (i >= end || s[i] != ')') return std::nullopt;
        ++i;
    }
    return i;
}

// Where the macro's replacement list starts: past `#define NAME` and a parameter list.
size_t bodyStart(const std::string& s, size_t start, size_t end) {
    size_t i = s.find("define", start) + 6;
    i = skipSpaces(s, i, end);
    while (i < end && isWordChar(s[i])) ++i;
    if (i < end && s[i] == '(') {
        while (i < end && s[i] != ')') ++i;
        ++i;
    }
    return i;
}

// The condition of the ?: at q: back to the bracket or comma that opens it at its depth (`body`
// where none does).
size_t conditionStart(const std::string& s, size_t body, size_t q) {
    int depth = 0;
    for (size_t k = q; k-- > body;) {
        if (s[k] == ')') ++depth;
        else if (s[k] == '(' && depth-- == 0) return k + 1;
        else if (s[k] == ',' && depth == 0) return k + 1;
    }
    return body;
}

// No other ?: at the condition's own depth (`p ? q : r ? 1 : 0`: the ?: is r's).
bool alone(const std::string& cond) {
    int depth = 0;
    for (char c : cond) {
        if (c == '(') ++depth;
        else if (c == ')') --depth;
        else if ((c == '?' || c == ':') && depth == 0) return false;
    }
    return true;
}

}  // namespace

void integerTernariesAsArithmetic(std::string& text, size_t start, size_t& end) {
    const size_t body = bodyStart(text, start, end);
    if (text.find("//", body) < end || text.find("/*", body) < end || text.find('"', body) < end) return;  // kept simple
    for (size_t q = text.find('?', body); q < end; q = text.find('?', q + 1)) {
        auto thenEnd = integerOperand(text, q + 1, end);
        if (!thenEnd) continue;
        size_t colon = skipSpaces(text, *thenEnd, end);
        if (colon >= end || text[colon] != ':') continue;
        auto elseEnd = integerOperand(text, colon + 1, end);
        if (!elseEnd) continue;
        // Only a ?: in its own parentheses: bare, its operands would bind differently to what
        // surrounds the macro's use.
        size_t after = skipSpaces(text, *elseEnd, end);
        size_t condBegin = conditionStart(text, body, q);
        if (after >= end || text[after] != ')' || condBegin == body || text[condBegin - 1] != '(') continue;
        std::string cond = text.substr(condBegin, q - condBegin);
        if (cond.find_first_not_of(" \t") == std::string::npos || !alone(cond)) continue;
        const std::string a = text.substr(q + 1, *thenEnd - q - 1), b = text.substr(colon + 1, *elseEnd - colon - 1);
        const std::string arithmetic = "(((" + cond + ") != 0) * (" + a + ") + ((" + cond + ") == 0) * (" + b + "))";
        text.replace(condBegin, *elseEnd - condBegin, arithmetic);
        end += arithmetic.size() - (*elseEnd - condBegin);
        q = condBegin + arithmetic.size() - 1;
    }
}

}  // namespace fxport::xlate
