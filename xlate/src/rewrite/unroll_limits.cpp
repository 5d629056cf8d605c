// See unroll_limits.h.
#include "rewrite/unroll_limits.h"

#include <string>

namespace fxport::xlate {

namespace {

// Index of the token closing the bracket opened at `open` (`end` when unbalanced).
size_t closing(const std::vector<Token>& t, size_t open, size_t end) {
    int depth = 0;
    for (size_t i = open; i < end; ++i) {
        if (t[i].is("(") || t[i].is("[") || t[i].is("{")) ++depth;
        if ((t[i].is(")") || t[i].is("]") || t[i].is("}")) && --depth == 0) return i;
    }
    return end;
}

// One past the loop body that starts at `i`: a block, or a plain statement to its `;`. Nothing
// (0) for a body that is itself a control statement (its end needs a parser).
size_t bodyEnd(const std::vector<Token>& t, size_t i, size_t end) {
    if (i >= end) return 0;
    if (t[i].is("{")) return closing(t, i, end) + 1;
    for (const char* w : {"if", "for", "while", "do", "switch", "["})
        if (t[i].is(w)) return 0;
    for (int depth = 0; i < end; ++i) {
        if (t[i].is("(") || t[i].is("[") || t[i].is("{")) ++depth;
        if (t[i].is(")") || t[i].is("]") || t[i].is("}")) --depth;
        if (depth == 0 && t[i].is(";")) return i + 1;
    }
    return 0;
}

// The condition of the loop whose keyword is at `k`: [begin, end) of its tokens, and one past the
// loop's header. Nothing for a `do` loop or an unbalanced header.
struct Header {
    size_t condBegin = 0, condEnd = 0, close = 0;
};
bool loopHeader(const std::vector<Token>& t, size_t k, size_t end, Header& h) {
    if (k + 1 >= end || !t[k + 1].is("(")) return false;
    h.close = closing(t, k + 1, end);
    if (h.close >= end) return false;
    if (t[k].is("while")) {
        h.condBegin = k + 2, h.condEnd = h.close;
        return true;
    }
    size_t semis[2] = {0, 0};
    int found = 0, depth = 0;
    for (size_t i = k + 2; i < h.close && found < 2; ++i) {
        if (t[i].is("(") || t[i].is("[") || t[i].is("{")) ++depth;
        if (t[i].is(")") || t[i].is("]") || t[i].is("}")) --depth;
        if (depth == 0 && t[i].is(";")) semis[found++] = i;
    }
    if (found < 2) return false;
    h.condBegin = semis[0] + 1, h.condEnd = semis[1];
    return true;
}

std::string textOf(const std::vector<Token>& t, size_t begin, size_t end) {
    std::string s;
    for (size_t i = begin; i < end; ++i) s += (s.empty() ? "" : " ") + t[i].text;
    return s;
}

}  // namespace

std::vector<TextEdit> unrollLimitsAsConditions(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const auto& f : syntax.functions) {
        const size_t end = f.body.end;
        for (size_t i = f.body.begin; i + 4 < end; ++i) {
            if (!(t[i].is("[") && t[i + 1].is("unroll") && t[i + 2].is("("))) continue;
            const size_t limitClose = closing(t, i + 2, end);
            if (limitClose + 1 >= end || limitClose == i + 3 || !t[limitClose + 1].is("]")) continue;
            // The statement's first attribute, and the loop keyword after the last one.
            size_t first = i;
            while (first > f.body.begin && t[first - 1].is("]")) {
                size_t open = first - 1;
                for (int depth = 0; open > f.body.begin; --open) {
                    if (t[open].is("]")) ++depth;
                    if (t[open].is("[") && --depth == 0) break;
                }
                if (!t[open].is("[") || open == f.body.begin || !t[open + 1].isIdent()) break;
                first = open;
            }
            size_t k = limitClose + 2;
            while (k < end && t[k].is("[")) k = closing(t, k, end) + 1;
            Header h;
            if (k >= end || !(t[k].is("for") || t[k].is("while")) || !loopHeader(t, k, end, h)) continue;
            const std::string counter = "fxport_unroll" + std::to_string(i);
            const std::string limit = counter + "++ < (" + textOf(t, i + 3, limitClose) + ")";
            const Token& before = t[first - 1];
            const bool statementStart = first == f.body.begin || before.is(";") || before.is("{") || before.is("}") || before.is(":");
            size_t wrapEnd = statementStart ? 0 : bodyEnd(t, h.close + 1, end);
            if (!statementStart && wrapEnd == 0) continue;  // an unbraced body we cannot bound: left as it is
            edits.push_back({t[first].offset, t[first].offset, (statementStart ? "" : "{ ") + std::string("uint ") + counter + " = 0; "});
            if (h.condBegin == h.condEnd) {
                edits.push_back({t[h.condEnd].offset, t[h.condEnd].offset, limit});
            } else {
                edits.push_back({t[h.condBegin].offset, t[h.condBegin].offset, limit + " && ("});
                edits.push_back({t[h.condEnd].offset, t[h.condEnd].offset, ")"});
            }
            if (!statementStart) edits.push_back({t[wrapEnd - 1].end, t[wrapEnd - 1].end, " }"});
        }
    }
    return edits;
}

}  // namespace fxport::xlate
