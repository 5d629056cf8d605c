// See matrix_majority.h.
#include "matrix_majority.h"

#include <map>
#include <string>

#include "hlsl_types.h"

namespace fxport::xlate {

namespace {

bool isMajority(const Token& t) { return t.is("row_major") || t.is("column_major"); }

// Whether a modifier run before token `at` already names a majority.
bool hasOwnMajority(const std::vector<Token>& t, size_t at) {
    for (size_t k = at; k > 0 && t[k - 1].isIdent(); --k)
        if (isMajority(t[k - 1])) return true;
    return false;
}

}  // namespace

std::vector<TextEdit> spellOutPackMatrixPragmas(const EffectSyntax& syntax) {
    const std::vector<Token>& t = syntax.tokens;
    std::vector<TextEdit> edits;
    std::string current;  // empty until a pragma: glslang's default (column_major) stays
    std::map<size_t, size_t> bodies;  // begin -> end of each function body, skipped whole
    for (const auto& f : syntax.functions) bodies[f.body.begin] = f.body.end;
    for (size_t i = 0; i + 5 < t.size(); ++i) {
        if (auto body = bodies.find(i); body != bodies.end() && body->second > i) {
            i = body->second - 1;  // the loop's ++i lands on the body's end
            continue;
        }
        if (t[i].is("#") && t[i + 1].is("pragma") && t[i + 2].is("pack_matrix") && t[i + 3].is("(") && isMajority(t[i + 4]) &&
            t[i + 5].is(")") && t[i + 1].line == t[i].line) {
            current = t[i + 4].text;
            edits.push_back({t[i].offset, t[i + 5].end, ""});
            i += 5;
            continue;
        }
        if (current.empty() || !t[i].isIdent() || !t[i + 1].isIdent()) continue;
        if (i > 0 && (t[i - 1].is("typedef") || t[i - 1].is("."))) continue;  // a typedef takes majority where it is used
        BasicType type = describeBasicType(syntax.resolveType(t[i].text));
        if (!type.ok || !type.isMatrix || hasOwnMajority(t, i)) continue;
        edits.push_back({t[i].offset, t[i].offset, current + " "});
    }
    return edits;
}

}  // namespace fxport::xlate
