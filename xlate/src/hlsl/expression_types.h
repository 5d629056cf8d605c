// The HLSL type of an expression in a function body, found from the tokens alone (before glslang
// runs), with fxc's rules: literals (`1` int, `1.0` float, `1u` uint), variables as declared
// (variable_declarations.h), struct members, swizzles, indexing (a structured buffer of structs
// gives its struct), casts, constructors, the effect's own functions, the common intrinsics, and
// the operators' common type (a scalar or a one-component value takes the other's shape; two
// vectors the smaller; two matrices the smaller rows and columns; the component type float > uint
// > int, bool arithmetic as int).
// Nothing where anything is not evident, so a rewrite built on it changes only what it understands.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fx/fx_syntax.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

struct ExpressionType {
    BasicType basic;           // numeric when basic.ok (scalar, vector or matrix)
    std::string structName;    // a struct's name (typedefs resolved) when not numeric
    std::vector<int> dims;     // array sizes, outermost first (0: none known, a structured buffer of structs)
    bool vector1 = false;      // a one-component vector (float1, vector<float, 1>), not a scalar
    // A one-row or one-column matrix that stays a matrix to glslang (a uniform, a struct member, an
    // entry input: degenerate_matrices.h), or a value computed from one: glslang's type is not
    // the vector a rewrite would assume.
    bool keptMatrix = false;
    bool isNumeric() const { return basic.ok && structName.empty() && dims.empty(); }
};

// fxc's result of mul(a, b) (both numeric): a scalar scales; a vector is a row on the left and a
// column on the right; the inner dimension is the smaller of the two (mul(float1, float4x4) is
// the first row times the one component).
ExpressionType productType(const ExpressionType& a, const ExpressionType& b);

// A binary operation met on the way: its operator (`<<` and `<=` as one), its operands' token
// spans and types (both numeric) and its result's type.
struct BinaryOperation {
    size_t leftBegin = 0, leftEnd = 0, rightBegin = 0, rightEnd = 0;
    BasicType left, right, result;
    std::string op;
    bool keptMatrix = false;  // either operand is (see ExpressionType)
};

// A `c ? a : b` met on the way: the tokens of its condition's start, '?', ':' and its end; the
// types of the condition, of each branch and of the result.
struct Selection {
    size_t begin = 0, question = 0, colon = 0, end = 0;
    ExpressionType condition, first, second, result;
};

// A unary minus met on the way: the `-` token, the end of its operand and the operand's type.
struct Negation {
    size_t minus = 0, end = 0;
    ExpressionType operand;
};

// What an expression is made of, as far as the rewrites that retype operations need it.
struct ExpressionParts {
    std::vector<BinaryOperation> operations;
    std::vector<Selection> selections;
    std::vector<Negation> negations;
};

// The type of tokens [begin, end) of `f`'s body; `parts`, when given, receives the operations
// inside (only when the whole expression has a type).
std::optional<ExpressionType> expressionType(const EffectSyntax& syntax, const FxFunction& f, size_t begin, size_t end,
                                             ExpressionParts* parts = nullptr);

// fxc's spelling of a numeric type: float, float3, float2x3.
std::string spellType(const BasicType& b);

// glslang's component type for fxc's: half and the min-precision types are float to it, dword
// and min16uint uint, the other min-precision types int.
std::string glslangScalar(const std::string& s);

// How glslang spells fxc's type: a one-row or one-column matrix is a vector to it
// (degenerate_matrices.h), a one-component one a scalar.
std::string glslangSpelling(BasicType b);

// The component type of an operation between `a` and `b` (float beats uint beats int; bool,
// half and the min-precision types count as int and float).
std::string commonScalar(const std::string& a, const std::string& b);

}  // namespace fxport::xlate
