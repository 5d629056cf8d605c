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

// Each '{' token's matching '}' (the end of the tokens when there is none).
std::vector<size_t> matchingBraces(const std::vector<Token>& t) {
    std::vector<size_t> close(t.size(), t.size()), open;
    for (size_t i = 0; i < t.size(); ++i) {
        if (t[i].is("{")) open.push_back(i);
        if (t[i].is("}") && !open.empty()) {
            close[open.back()] = i;
            open.pop_back();
        }
    }
    return close;
}

}  // namespace

// A constant declared in a block of a function body is that block's (fxc scopes them as C does:
// two functions may each have their own `const int n`); other braces (a cbuffer's, a struct's) do
// not scope, a `static const` in a cbuffer is a global.
ConstantSizes::ConstantSizes(const EffectSyntax& syntax) : syntax_(syntax) {
    const auto& t = syntax.tokens;
    std::vector<bool> bodyOpens(t.size(), false);
    for (const auto& f : syntax.functions)
        if (f.body.begin >= 1 && f.body.begin - 1 < t.size()) bodyOpens[f.body.begin - 1] = true;
    const std::vector<size_t> close = matchingBraces(t);
    std::vector<size_t> blocks;  // where the open blocks of function bodies end, innermost last
    for (size_t i = 0; i + 4 < t.size(); ++i) {
        while (!blocks.empty() && i >= blocks.back()) blocks.pop_back();
        if (t[i].is("{") && (bodyOpens[i] || !blocks.empty())) blocks.push_back(close[i]);
        if (t[i].is("const")) remember(i, blocks.empty() ? t.size() : blocks.back());
    }
}

// `[static] const T name = expr;` of a scalar type T at the `const` token `at` (or an array of
// them, see rememberArray), visible until `scopeEnd`.
void ConstantSizes::remember(size_t at, size_t scopeEnd) {
    const auto& t = syntax_.tokens;
    size_t j = at + 1;
    if (t[j].is("static")) ++j;
    if (j + 3 >= t.size() || !t[j].isIdent() || !t[j + 1].isIdent()) return;
    BasicType b = describeBasicType(syntax_.resolveType(t[j].text));
    if (!b.ok || b.rows * b.columns != 1) return rememberTyped(j, scopeEnd);
    if (t[j + 2].is("[")) return rememberArray(j, scopeEnd, b);
    if (!t[j + 2].is("=")) return;
    size_t end = j + 3;
    while (end < t.size() && !t[end].is(";") && t[end].kind != Token::Kind::End) ++end;
    auto v = evaluate({j + 3, end});
    if (!v || v->size() != 1) return;
    // The constant holds its type's value: an int truncates what it is given.
    const double value = b.scalar == "float" || b.scalar == "half" || b.scalar == "double" ? (*v)[0] : std::trunc((*v)[0]);
    constants_[t[j + 1].text].push_back({j + 1, scopeEnd, false, {value}});
}

// `[static] const T name[N] = { ... };` of a scalar type T, at the type token `type`: its N values
// (in T: an int array truncates), for sizes that index it (`float b[w[2]]`, vkd3d's array-size-expr).
void ConstantSizes::rememberArray(size_t type, size_t scopeEnd, const BasicType& b) {
    const auto& t = syntax_.tokens;
    size_t close = type + 3;
    while (close < t.size() && !t[close].is("]") && !t[close].is(";") && t[close].kind != Token::Kind::End) ++close;
    if (close + 1 >= t.size() || !t[close].is("]") || !t[close + 1].is("=")) return;
    auto count = size(type + 2, close);
    size_t end = close + 2;
    while (end < t.size() && !t[end].is(";") && t[end].kind != Token::Kind::End) ++end;
    auto v = evaluate({close + 2, end});
    if (!count || !v || v->size() != size_t(*count)) return;
    const bool real = b.scalar == "float" || b.scalar == "half" || b.scalar == "double";
    for (double& x : *v) x = real ? x : std::trunc(x);
    constants_[t[type + 1].text].push_back({type + 1, scopeEnd, true, std::move(*v)});
}

// `[static] const T name[N]... = ...;` of a vector, matrix or struct type T (or an array of
// scalars with more than one size), at the type token `type`: its components (typedConstant).
void ConstantSizes::rememberTyped(size_t type, size_t scopeEnd) {
    const auto& t = syntax_.tokens;
    size_t j = type + 2;
    std::vector<int> dims;
    while (j + 1 < t.size() && t[j].is("[")) {
        size_t close = j + 1;
        while (close < t.size() && !t[close].is("]") && !t[close].is(";") && t[close].kind != Token::Kind::End) ++close;
        auto n = close < t.size() && t[close].is("]") ? size(j, close) : std::nullopt;
        if (!n || *n == 0) return;
        dims.push_back(*n);
        j = close + 1;
    }
    if (j >= t.size() || !t[j].is("=")) return;
    size_t end = j + 1;
    while (end < t.size() && !t[end].is(";") && t[end].kind != Token::Kind::End) ++end;
    auto v = evaluate({j + 1, end});
    if (auto c = v ? typedConstant(syntax_, t[type].text, dims, std::move(*v)) : std::nullopt)
        typed_[t[type + 1].text].push_back({type + 1, scopeEnd, std::move(*c)});
}

const TypedConstant* ConstantSizes::visibleTyped(const std::string& name, size_t at) const {
    auto it = typed_.find(name);
    if (it == typed_.end()) return nullptr;
    for (auto c = it->second.rbegin(); c != it->second.rend(); ++c)
        if (c->from < at && at < c->to) return &c->value;
    return nullptr;
}

// The value of the constant `name` (an array's when `array`) that token `at` sees: the latest
// declared before it whose block is still open there.
const std::vector<double>* ConstantSizes::visible(const std::string& name, bool array, size_t at) const {
    auto it = constants_.find(name);
    if (it == constants_.end()) return nullptr;
    for (auto c = it->second.rbegin(); c != it->second.rend(); ++c)
        if (c->from < at && at < c->to) return c->array == array ? &c->values : nullptr;
    return nullptr;
}

std::optional<std::vector<double>> ConstantSizes::evaluate(TokenSpan span) const {
    const TypedConstantLookup typed = [this, span](const std::string& name) { return visibleTyped(name, span.begin); };
    return evaluateConstantWith(
        syntax_, span, [this, span](const std::string& name, bool array) { return visible(name, array, span.begin); }, nullptr, false, &typed);
}

std::optional<int> ConstantSizes::size(size_t open, size_t close) const {
    if (close == open + 1) return 0;
    if (close == open + 2 && isIntegerLiteral(syntax_.tokens[open + 1])) return std::atoi(syntax_.tokens[open + 1].text.c_str());
    auto v = evaluate({open + 1, close});
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
