// See local_state_blocks.h.
#include "rewrite/local_state_blocks.h"

namespace fxport::xlate {

namespace {

bool isStatementWord(const Token& t) {
    for (const char* k : {"return", "else", "do", "case", "default", "break", "continue", "discard", "goto", "in", "out", "inout"})
        if (t.is(k)) return true;
    return false;
}

// The `{` matching the `}` at `close`, searching back no further than `from`; `close` when none.
size_t openingBrace(const std::vector<Token>& t, size_t from, size_t close) {
    int depth = 0;
    for (size_t k = close + 1; k-- > from;) {
        if (t[k].is("}")) ++depth;
        else if (t[k].is("{") && --depth == 0) return k;
    }
    return close;
}

// Whether t[i] (an identifier before `{`) is a variable's name: a type's name or the `}` of an
// anonymous or named struct's body comes before it (not `else {`, `do {`, `) {`).
bool namesAVariable(const std::vector<Token>& t, size_t bodyBegin, size_t i) {
    if (i == 0 || isStatementWord(t[i])) return false;
    const Token& before = t[i - 1];
    if (before.isIdent()) return !isStatementWord(before);
    if (before.is(">")) return true;  // vector<float, 2> v { ... }
    if (!before.is("}")) return false;
    size_t open = openingBrace(t, bodyBegin, i - 1);
    if (open == i - 1 || open == 0) return false;
    return t[open - 1].is("struct") || (open >= 2 && t[open - 1].isIdent() && t[open - 2].is("struct"));
}

// The token after the `}` closing the block that opens at `open`; 0 when it does not close in `end`.
size_t afterBlock(const std::vector<Token>& t, size_t open, size_t end) {
    int depth = 0;
    for (size_t k = open; k < end; ++k) {
        if (t[k].is("{")) ++depth;
        else if (t[k].is("}") && --depth == 0) return k + 1;
    }
    return 0;
}

}  // namespace

std::vector<TextEdit> localStateBlocksDropped(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const auto& f : syntax.functions)
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
            if (!t[i].isIdent() || !t[i + 1].is("{") || !namesAVariable(t, f.body.begin, i)) continue;
            size_t after = afterBlock(t, i + 1, f.body.end);
            // A declaration goes on after its block with `;` or `,`.
            if (!after || !(t[after].is(";") || t[after].is(","))) continue;
            edits.push_back({t[i + 1].offset, t[after - 1].end, ""});
            i = after - 1;
        }
    return edits;
}

}  // namespace fxport::xlate
