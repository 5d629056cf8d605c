// See array_sizes.h.
#include "rewrite/array_sizes.h"

#include <cmath>

#include "fx/constant_eval.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

bool isIntegerLiteral(const Token& t) {
    return t.kind == Token::Kind::Number && t.text.find_first_not_of("0123456789") == std::string::npos;
}

// `[` at i begins a declarator's size: after the declared name (itself after a type or a modifier
// word) or after another size of the same declarator.
bool declaratorSizeAt(const EffectSyntax& syntax, size_t i) {
    const auto& t = syntax.tokens;
    size_t at = i;
    while (at >= 1 && t[at - 1].is("]")) {  // `float a[2][N]`: back over the earlier sizes
        int depth = 0;
        size_t k = at - 1;
        for (; k > 0; --k) {
            if (t[k].is("]")) ++depth;
            if (t[k].is("[") && --depth == 0) break;
        }
        if (depth != 0) return false;
        at = k;
    }
    if (at < 2 || !t[at - 1].isIdent() || !t[at - 2].isIdent()) return false;
    const std::string& type = syntax.resolveType(t[at - 2].text);
    return describeBasicType(type).ok || syntax.findStruct(type) != nullptr;
}

}  // namespace

ConstantSizes::ConstantSizes(const EffectSyntax& syntax) : syntax_(syntax) {
    const auto& t = syntax.tokens;
    for (size_t i = 0; i + 4 < t.size(); ++i) {
        if (!t[i].is("const")) continue;
        size_t j = i + 1;
        if (t[j].is("static")) ++j;
        if (j + 3 >= t.size() || !t[j].isIdent() || !t[j + 1].isIdent()) continue;
        BasicType b = describeBasicType(syntax.resolveType(t[j].text));
        if (!b.ok || b.rows * b.columns != 1) continue;
        if (t[j + 2].is("[")) {
            rememberArray(j, b);
            continue;
        }
        if (!t[j + 2].is("=")) continue;
        size_t end = j + 3;
        while (end < t.size() && !t[end].is(";") && t[end].kind != Token::Kind::End) ++end;
        auto v = evaluateConstant(syntax, {j + 3, end}, known_, nullptr, &arrays_);
        if (!v || v->size() != 1) continue;
        // The constant holds its type's value: an int truncates what it is given.
        known_[t[j + 1].text] = {b.scalar == "float" || b.scalar == "half" || b.scalar == "double" ? (*v)[0] : std::trunc((*v)[0])};
    }
}

// `[static] const T name[N] = { ... };` of a scalar type T, at the type token `type`: its N values
// (in T: an int array truncates), for sizes that index it (`float b[w[2]]`, vkd3d's array-size-expr).
void ConstantSizes::rememberArray(size_t type, const BasicType& b) {
    const auto& t = syntax_.tokens;
    size_t close = type + 3;
    while (close < t.size() && !t[close].is("]") && !t[close].is(";") && t[close].kind != Token::Kind::End) ++close;
    if (close + 1 >= t.size() || !t[close].is("]") || !t[close + 1].is("=")) return;
    auto count = size(type + 2, close);
    size_t end = close + 2;
    while (end < t.size() && !t[end].is(";") && t[end].kind != Token::Kind::End) ++end;
    auto v = evaluateConstant(syntax_, {close + 2, end}, known_, nullptr, &arrays_);
    if (!count || !v || v->size() != size_t(*count)) return;
    const bool real = b.scalar == "float" || b.scalar == "half" || b.scalar == "double";
    for (double& x : *v) x = real ? x : std::trunc(x);
    arrays_[t[type + 1].text] = std::move(*v);
}

std::optional<int> ConstantSizes::size(size_t open, size_t close) const {
    if (close == open + 1) return 0;
    if (close == open + 2 && isIntegerLiteral(syntax_.tokens[open + 1])) return std::atoi(syntax_.tokens[open + 1].text.c_str());
    auto v = evaluateConstant(syntax_, {open + 1, close}, known_, nullptr, &arrays_);
    if (!v || v->size() != 1 || !std::isfinite((*v)[0]) || (*v)[0] < 1 || (*v)[0] > 65536.0) return std::nullopt;
    return static_cast<int>((*v)[0]);  // fxc truncates a float size
}

std::vector<TextEdit> arraySizesAsLiterals(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    ConstantSizes sizes(syntax);
    std::vector<TextEdit> edits;
    for (size_t i = 0; i < t.size(); ++i) {
        if (!t[i].is("[") || !declaratorSizeAt(syntax, i)) continue;
        int depth = 0;
        size_t close = i;
        for (; close < t.size() && t[close].kind != Token::Kind::End; ++close) {
            if (t[close].is("[")) ++depth;
            if (t[close].is("]") && --depth == 0) break;
        }
        if (depth != 0 || close == i + 1 || (close == i + 2 && isIntegerLiteral(t[i + 1]))) continue;
        if (auto n = sizes.size(i, close)) edits.push_back({t[i + 1].offset, t[close - 1].end, std::to_string(*n)});
        i = close;
    }
    // `Texture2DMS<float4, size - 1>`: the sample count is such a constant too.
    for (size_t i = 0; i + 4 < t.size(); ++i) {
        if (!(t[i].is("Texture2DMS") || t[i].is("Texture2DMSArray")) || !t[i + 1].is("<") || !t[i + 2].isIdent() || !t[i + 3].is(",")) continue;
        size_t close = i + 4;
        while (close < t.size() && !t[close].is(">") && !t[close].is(";") && t[close].kind != Token::Kind::End) ++close;
        if (!t[close].is(">") || close == i + 4 || (close == i + 5 && isIntegerLiteral(t[i + 4]))) continue;
        if (auto n = sizes.size(i + 3, close)) edits.push_back({t[i + 4].offset, t[close - 1].end, std::to_string(*n)});
    }
    return edits;
}

}  // namespace fxport::xlate
