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

// A constant of a vector, matrix or struct type, or an array of them: its type as declared, its
// array sizes (outermost first) and its components in declaration order (a matrix row by row, a
// struct member by member). Read through subscripts, members and swizzles (`a.m[1]._13_22.y`,
// vkd3d's array-size-expr L71) down to numbers.
struct TypedConstant {
    std::string type;
    std::vector<int> dims;
    std::vector<double> values;
};
using TypedConstantLookup = std::function<const TypedConstant*(const std::string& name)>;

// How many components a value of `type` (typedefs resolved) with array sizes `dims` holds, and
// the scalar type of each in order; nothing for a type that is not numbers all through.
std::optional<std::vector<std::string>> componentScalars(const EffectSyntax& syntax, const std::string& type, const std::vector<int>& dims);

// The constant of `type` and `dims` that an initializer's flat `values` make: each component in
// its scalar type (an int truncates, as fxc stores it); nothing when the count differs.
std::optional<TypedConstant> typedConstant(const EffectSyntax& syntax, const std::string& type, const std::vector<int>& dims,
                                           std::vector<double> values);

std::optional<std::vector<double>> evaluateConstantWith(const EffectSyntax& syntax, TokenSpan span, const ConstantLookup& lookup,
                                                        bool* tooDeep = nullptr, bool integers = false,
                                                        const TypedConstantLookup* typed = nullptr);

}  // namespace fxport::xlate
