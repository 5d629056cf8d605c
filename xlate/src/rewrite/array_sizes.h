// Array sizes written as constant expressions, as fxc takes them: `float4 a[(2 + 1) * 2]`,
// `float c[dim]` after `const int dim = 4;` (a local constant too), `float d[true]`, `float b[4.1]`
// (fxc truncates: 4). glslang wants a constant integer expression and refuses a float, a bool or a
// local constant there ("array size must be a constant integer expression"); vkd3d's
// array-size-expr and array-dimension pin these. In every declaration such a size becomes the
// integer literal fxc computes, and so does the sample count of `Texture2DMS<float4, size - 1>`;
// a size constant_eval cannot evaluate is left to glslang.
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fx/fx_syntax.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

class ConstantSizes {
public:
    // Scalar constants (`[static] const T name = expr;` anywhere, in order) are evaluated once.
    explicit ConstantSizes(const EffectSyntax& syntax);

    // The size written between the brackets at tokens `open` ('[') and `close` (']'): 0 for `[]`,
    // nothing when it is not a constant.
    std::optional<int> size(size_t open, size_t close) const;

private:
    void rememberArray(size_t type, const BasicType& b);
    const EffectSyntax& syntax_;
    std::map<std::string, std::vector<double>> known_;
    std::map<std::string, std::vector<double>> arrays_;  // constant arrays of scalars, for `w[i]` in a size
};

std::vector<TextEdit> arraySizesAsLiterals(const EffectSyntax& syntax);

}  // namespace fxport::xlate
