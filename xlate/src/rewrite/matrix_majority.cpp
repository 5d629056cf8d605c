// See matrix_majority.h.
#include "rewrite/matrix_majority.h"

#include <map>
#include <string>

#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

bool isMajority(const Token& t) { return t.is("row_major") || t.is("column_major"); }

// The majority a modifier run before token `at` names, or "".
std::string ownMajority(const std::vector<Token>& t, size_t at) {
    for (size_t k = at; k > 0 && t[k - 1].isIdent(); --k)
        if (isMajority(t[k - 1])) return t[k - 1].text;
    return {};
}

// Whether the modifier run before token `at` starts with `typedef`.
bool inTypedef(const std::vector<Token>& t, size_t at) {
    for (size_t k = at; k > 0 && t[k - 1].isIdent(); --k)
        if (t[k - 1].is("typedef")) return true;
    return false;
}

}  // namespace

std::vector<TextEdit> spellOutPackMatrixPragmas(const EffectSyntax& syntax, const std::string& defaultMajority) {
    const std::vector<Token>& t = syntax.tokens;
    std::vector<TextEdit> edits;
    std::string current = defaultMajority;  // empty until a pragma: glslang's default (column_major) stays
    std::map<std::string, std::string> latent;  // matrix typedef -> the majority it was declared under
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
        if (!t[i].isIdent() || !t[i + 1].isIdent() || (i > 0 && t[i - 1].is("."))) continue;
        const std::string own = ownMajority(t, i);
        // A typedef of a matrix after a pragma (or with a majority of its own) keeps that majority
        // wherever it is used (fxc); one before any pragma has none and takes the majority of its
        // use. glslang ignores a majority written in a typedef, so it is written at each use.
        if (auto fixed = latent.find(t[i].text); fixed != latent.end()) {
            if (inTypedef(t, i)) latent[t[i + 1].text] = own.empty() ? fixed->second : own;
            else if (own.empty()) edits.push_back({t[i].offset, t[i].offset, fixed->second + " "});
            continue;
        }
        BasicType type = describeBasicType(syntax.resolveType(t[i].text));
        if (!type.ok || !type.isMatrix) continue;
        if (inTypedef(t, i)) {
            if (!(own.empty() ? current : own).empty()) latent[t[i + 1].text] = own.empty() ? current : own;
            continue;
        }
        if (own.empty() && !current.empty()) edits.push_back({t[i].offset, t[i].offset, current + " "});
    }
    return edits;
}

}  // namespace fxport::xlate
