// fxc's signature layout rules shared by the entry wrapper and the semantic checks (see
// signature_layout.h).
#include "entry/signature_layout.h"

#include <algorithm>

#include "entry/entry_wrapper.h"

namespace fxport::xlate {

namespace {

bool rowMajor(const std::vector<std::string>& modifiers) {
    return std::find(modifiers.begin(), modifiers.end(), "row_major") != modifiers.end();
}

}  // namespace

int signatureRegisters(const BasicType& b, const std::vector<std::string>& modifiers) {
    if (!b.isMatrix) return 1;
    return rowMajor(modifiers) ? b.rows : b.columns;
}

int signatureWidth(const BasicType& b, const std::vector<std::string>& modifiers) {
    if (!b.isMatrix) return b.columns;
    return rowMajor(modifiers) ? b.columns : b.rows;
}

SemanticCascade SemanticCascade::from(const std::string& semantic) {
    SemanticCascade c;
    if (semantic.empty()) return c;
    auto [base, index] = splitSemantic(semantic);
    c.active = true;
    c.base = base;
    c.next = index;
    return c;
}

std::pair<std::string, int> SemanticCascade::take(int registers) {
    int first = next;
    next += registers;
    return {base, first};
}

std::vector<std::string> entryReturnModifiers(const EffectSyntax& syntax, const FxFunction& entry) {
    std::vector<std::string> out;
    for (size_t k = entry.declaration.begin; k < entry.token && k < syntax.tokens.size(); ++k)
        if (syntax.tokens[k].is("row_major") || syntax.tokens[k].is("column_major")) out.push_back(syntax.tokens[k].text);
    return out;
}

std::vector<std::string> arrayElementAccesses(const std::string& access, const std::vector<int>& dims, size_t limit) {
    std::vector<std::string> out{access};
    for (int d : dims) {
        if (d <= 0 || out.size() * size_t(d) > limit) return {};
        std::vector<std::string> next;
        for (const auto& a : out)
            for (int i = 0; i < d; ++i) next.push_back(a + "[" + std::to_string(i) + "]");
        out.swap(next);
    }
    return out;
}

}  // namespace fxport::xlate
