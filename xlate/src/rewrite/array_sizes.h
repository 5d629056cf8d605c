// Array sizes written as constant expressions, as fxc takes them: `float4 a[(2 + 1) * 2]`,
// `float c[dim]` after `const int dim = 4;` (a local constant too), `float d[true]`, `float b[4.1]`
// (fxc truncates: 4), `float e[v.y * s.m[1]._22]` of vector, matrix and struct constants. glslang wants a constant integer expression and refuses a float, a bool or a
// local constant there ("array size must be a constant integer expression"); vkd3d's
// array-size-expr and array-dimension pin these. In every declaration such a size becomes the
// integer literal fxc computes, and so does the sample count of `Texture2DMS<float4, size - 1>`;
// a size constant_eval cannot evaluate is left to glslang.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fx/constant_eval.h"
#include "fx/fx_syntax.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

class ConstantSizes {
public:
    // Scalar constants (`[static] const T name = expr;` anywhere, in order) are evaluated once.
    explicit ConstantSizes(const EffectSyntax& syntax);

    // The size written between the brackets at tokens `open` ('[') and `close` (']'): 0 for `[]`,
    // nothing when it is not a constant. Names mean the constants visible at `open`.
    std::optional<int> size(size_t open, size_t close) const;

private:
    // A constant with the tokens where it is visible: from its declaration to the end of the block
    // that declares it (a function's local, fxc's scoping) or of the file (a global).
    struct Scoped {
        size_t from = 0, to = 0;
        bool array = false;
        std::vector<double> values;
    };
    void remember(size_t type, size_t scopeEnd);
    void rememberArray(size_t type, size_t scopeEnd, const BasicType& b);
    void rememberTyped(size_t type, size_t scopeEnd);
    std::optional<std::vector<double>> evaluate(TokenSpan span) const;
    const std::vector<double>* visible(const std::string& name, bool array, size_t at) const;
    const TypedConstant* visibleTyped(const std::string& name, size_t at) const;
    const EffectSyntax& syntax_;
    // Each name's constants in declaration order: an inner block's, declared later, hides an outer one.
    std::map<std::string, std::vector<Scoped>> constants_;
    // The vector, matrix and struct constants (and arrays of them), likewise.
    struct ScopedTyped {
        size_t from = 0, to = 0;
        TypedConstant value;
    };
    std::map<std::string, std::vector<ScopedTyped>> typed_;
};

std::vector<TextEdit> arraySizesAsLiterals(const EffectSyntax& syntax);

}  // namespace fxport::xlate
