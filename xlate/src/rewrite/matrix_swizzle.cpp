// See matrix_swizzle.h: rewrites matrix swizzles of several elements into row indexing or a vector
// constructor of single-element swizzles.
#include "rewrite/matrix_swizzle.h"

#include <optional>
#include <set>
#include <string>

namespace fxport::xlate {

std::optional<std::vector<MatrixSwizzleElement>> parseMatrixSwizzle(const std::string& s) {
    std::vector<MatrixSwizzleElement> elements;
    size_t i = 0;
    bool zeroBased = s.size() > 1 && s[1] == 'm';
    while (i < s.size()) {
        if (s[i] != '_') return std::nullopt;
        MatrixSwizzleElement e;
        size_t start = i++;
        if (zeroBased) {
            if (i >= s.size() || s[i] != 'm') return std::nullopt;
            ++i;
        }
        if (i + 2 > s.size()) return std::nullopt;
        int r = s[i] - '0', c = s[i + 1] - '0';
        int lo = zeroBased ? 0 : 1;
        if (r < lo || r > lo + 3 || c < lo || c > lo + 3) return std::nullopt;
        e.row = r - lo;
        e.column = c - lo;
        i += 2;
        e.text = s.substr(start, i - start);
        elements.push_back(e);
    }
    if (elements.empty() || elements.size() > 4) return std::nullopt;
    return elements;
}

namespace {

// Index of the first token of the postfix expression that ends at token `last` (inclusive);
// nullopt if it is not one we can delimit.
std::optional<size_t> postfixStart(const std::vector<Token>& tokens, size_t last) {
    static const std::set<std::string> kKeywords = {"return", "if", "else", "while", "for", "do", "switch", "case"};
    size_t i = last;
    for (;;) {
        const Token& t = tokens[i];
        if (t.is(")") || t.is("]")) {
            const char* open = t.is(")") ? "(" : "[";
            int depth = 0;
            size_t j = i;
            for (;; --j) {
                if (tokens[j].is(t.text)) ++depth;
                else if (tokens[j].is(open) && --depth == 0) break;
                if (j == 0) return std::nullopt;
            }
            if (j == 0) return std::nullopt;
            bool call = t.is(")") && tokens[j - 1].isIdent() && !kKeywords.count(tokens[j - 1].text);
            if (t.is("]") || call) {
                i = j - 1;  // an index has its base before it; a call its function name
                continue;
            }
            return j;  // a parenthesised expression
        }
        if (t.isIdent() && !kKeywords.count(t.text)) {
            if (i >= 2 && tokens[i - 1].is(".")) {
                i -= 2;  // member access: keep going left
                continue;
            }
            return i;
        }
        return std::nullopt;
    }
}

// The token that ends the assigned expression starting at `from`: the `;` or `,` at its depth, or
// the bracket that closes around it.
size_t assignedExpressionEnd(const std::vector<Token>& tokens, size_t from) {
    int depth = 0;
    for (size_t k = from; k < tokens.size(); ++k) {
        const Token& t = tokens[k];
        if (t.is("(") || t.is("[") || t.is("{")) ++depth;
        else if ((t.is(")") || t.is("]") || t.is("}")) && depth-- == 0) return k;
        else if (depth == 0 && (t.is(";") || t.is(","))) return k;
        if (t.kind == Token::Kind::End) return k;
    }
    return tokens.size() - 1;
}

}  // namespace

std::vector<TextEdit> lowerMatrixSwizzles(const std::vector<Token>& tokens) {
    static const char* kComponents = "xyzw";
    std::vector<TextEdit> edits;
    for (size_t i = 1; i + 1 < tokens.size(); ++i) {
        if (!tokens[i].is(".") || !tokens[i + 1].isIdent()) continue;
        auto elements = parseMatrixSwizzle(tokens[i + 1].text);
        if (!elements || elements->size() < 2) continue;
        bool oneRow = true;
        for (const auto& e : *elements) oneRow = oneRow && e.row == elements->front().row;
        if (oneRow) {
            std::string r = "[" + std::to_string(elements->front().row) + "].";
            for (const auto& e : *elements) r += kComponents[e.column];
            edits.push_back({tokens[i].offset, tokens[i + 1].end, r});
            continue;
        }
        // Written (`m._m00_m11 = v`): a vector constructor is no l-value; glslang handles writes.
        const size_t after = i + 2 < tokens.size() ? i + 2 : i + 1;
        const Token& next = tokens[after];
        const bool written = next.kind == Token::Kind::Punct && !next.text.empty() && next.text.back() == '=' && next.text != "==" &&
                             next.text != "<=" && next.text != ">=" && next.text != "!=";
        auto start = postfixStart(tokens, i - 1);
        if (!start) continue;  // left to glslang, which reports it
        // The base's text as written (it may span lines: keep it on one line inside the constructor).
        std::string base;
        bool hasCall = false;
        for (size_t k = *start; k < i; ++k) {
            base += (k > *start ? " " : "") + tokens[k].text;
            hasCall = hasCall || tokens[k].is("(");
        }
        std::string r = "float" + std::to_string(elements->size()) + "(";
        for (size_t k = 0; k < elements->size(); ++k) r += (k ? ", " : "") + base + "." + (*elements)[k].text;
        r += ")";
        if (written) {
            // glslang writes only with `=`: `m._m00_m11 *= e` (helix-toolkit's gsLineArrowHead.hlsl)
            // is `m._m00_m11 = float2(m._m00, m._m11) * (e)`, the base read once more (so only a base
            // without calls, which could have effects).
            if (next.text == "=" || hasCall) continue;
            const std::string op = next.text.substr(0, next.text.size() - 1);
            const size_t end = assignedExpressionEnd(tokens, after + 1);
            edits.push_back({next.offset, next.end, "= " + r + " " + op + " ("});
            edits.push_back({tokens[end].offset, tokens[end].offset, ")"});
            continue;
        }
        edits.push_back({tokens[*start].offset, tokens[i + 1].end, r});
    }
    return edits;
}

}  // namespace fxport::xlate
