// See index_evaluation_order.h.
#include "rewrite/index_evaluation_order.h"

#include <set>
#include <string>

#include "hlsl/expression_types.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

// One past the bracket closing the one at `open` before `end`; 0 when it does not close.
size_t closing(const std::vector<Token>& t, size_t open, size_t end) {
    int depth = 0;
    for (size_t k = open; k < end; ++k) {
        if (t[k].is("(") || t[k].is("[") || t[k].is("{")) ++depth;
        if ((t[k].is(")") || t[k].is("]") || t[k].is("}")) && --depth == 0) return k + 1;
    }
    return 0;
}

std::string joined(const std::vector<Token>& t, size_t b, size_t e) {
    std::string s;
    for (size_t k = b; k < e; ++k) s += (k > b ? " " : "") + t[k].text;
    return s;
}

}  // namespace

std::vector<TextEdit> indexBeforeBaseForCalls(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    std::set<std::string> defined;
    auto callsEffectFunction = [&](size_t b, size_t e) {
        for (size_t k = b; k + 1 < e; ++k)
            if (t[k].isIdent() && t[k + 1].is("(") && !(k > 0 && t[k - 1].is(".")) && syntax.findFunction(t[k].text)) return true;
        return false;
    };
    for (const FxFunction& f : syntax.functions) {
        if (f.body.empty() || f.declaration.empty()) continue;
        std::string helpers;
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
            if (!t[i].isIdent() || !t[i + 1].is("(") || t[i - 1].is(".")) continue;
            const FxFunction* callee = syntax.findFunction(t[i].text);
            if (!callee) continue;
            const size_t open = closing(t, i + 1, f.body.end);  // one past the call's ')'
            if (!open || open >= f.body.end || !t[open].is("[")) continue;
            const size_t end = closing(t, open, f.body.end);
            if (!end || !callsEffectFunction(open + 1, end - 1) || t[i].line != t[end - 1].line) continue;
            bool nested = false;
            for (size_t k = open + 1; k + 1 < end; ++k) nested |= t[k].is("[");
            if (nested) continue;
            BasicType b = describeBasicType(syntax.resolveType(callee->returnType));
            if (!b.ok || (b.rows == 1 && b.columns == 1)) continue;
            const std::string base = spellType(b);
            BasicType element = b;
            if (b.isMatrix) {
                element.isMatrix = false;
                element.rows = 1;
            } else {
                element.columns = 1;
            }
            const std::string name = "fxport_index_" + base;
            if (defined.insert(name).second)
                helpers += spellType(element) + " " + name + "(int i, " + base + " v) { return v[i]; } ";
            // The base stays where it is (other rewrites may edit it); the index moves in front.
            edits.push_back({t[i].offset, t[i].offset, name + "(" + joined(t, open + 1, end - 1) + ", "});
            edits.push_back({t[open].offset, t[end - 1].end, ")"});
            i = end - 1;
        }
        if (!helpers.empty()) edits.push_back({t[f.declaration.begin].offset, t[f.declaration.begin].offset, helpers});
    }
    return edits;
}

}  // namespace fxport::xlate
