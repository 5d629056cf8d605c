// Parameter defaults: glslang drops global initializers, so we evaluate them ourselves.
// Handles literals, true/false, unary minus, + - * /, parentheses, constructors (float3(1, 2, 3)),
// brace lists ({1, 2, 3, 4}), min/max/abs/clamp and earlier globals by name. Anything else -> no
// default.
#pragma once

#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "fx/fx_syntax.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

// `tooDeep`, when given, is set when the expression nests deeper than limits::kMaxNesting (the
// result is then nullopt). `arrays`, when given, holds constant arrays of scalars by name, read by
// a constant index: `w[i]` (fxc sizes `float b[w[2]]` by it).
std::optional<std::vector<double>> evaluateConstant(const EffectSyntax& syntax, TokenSpan span,
                                                    const std::map<std::string, std::vector<double>>& known,
                                                    bool* tooDeep = nullptr,
                                                    const std::map<std::string, std::vector<double>>* arrays = nullptr);

// A name's value where the expression stands (constants are scoped): a scalar constant's when
// `array` is false, a constant array of scalars' when it is true; nullptr when there is none.
// `integers`: the expression is of integers, so `/` truncates toward zero as fxc's int division.
using ConstantLookup = std::function<const std::vector<double>*(const std::string& name, bool array)>;
std::optional<std::vector<double>> evaluateConstantWith(const EffectSyntax& syntax, TokenSpan span, const ConstantLookup& lookup,
                                                        bool* tooDeep = nullptr, bool integers = false);

}  // namespace fxport::xlate
