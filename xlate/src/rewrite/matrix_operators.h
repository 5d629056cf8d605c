// HLSL's operators on matrices compute per component, whatever the component type (HLSL
// "Operators": the arithmetic, bitwise, shift and comparison operators work per component on
// scalars, vectors and matrices; mul() is the linear-algebra product). glslang 12 does not:
//  - `A * B` and `A *= B` between two matrices are its OpMatrixTimesMatrix: the matrix product,
//    silently, for square ones; refused ("Could not perform requested binary operation") for
//    float2x3 * float2x3;
//  - arithmetic, bitwise and shift operators and `-` on int/uint/bool matrices crash it (SIGSEGV
//    in spv::Builder::createMatrixConstructor), their compound assignments fail ("Id is 0");
//  - comparisons of matrices, which give bool matrices, crash it.
// Such an operation becomes a call of a generated helper that computes row by row, on the
// vectors glslang handles: `e + 1` -> `fxport_matrix_add_int2x3_int(e, 1)`, `e &= 3` ->
// `fxport_matrix_and_assign_int2x3_int(e, 3)` (the target an inout parameter, so an index with
// side effects is evaluated once, and the value the assignment's, as in fxc). The helpers fill a
// local row by row: glslang also crashes on a bool matrix constructed from vectors.
// Only full matrices (two rows and two columns at least) with a scalar or a matrix of the same
// shape (mixed_shapes.h converts other shapes first); one-row and one-column matrices are
// vectors to glslang (degenerate_matrices.h), which computes them per component already.
#pragma once

#include <string>

#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

struct MatrixHelper {
    std::string name;
    std::string code;  // the definition, to go before the first function
};

// Whether `l op r` (op as written: `*`, `<<`, `<=` ...), whose fxc type is `result`, needs a helper.
bool needsRowwiseOperator(const std::string& op, const BasicType& l, const BasicType& r, const BasicType& result);
// `R name(L a, Rt b)`: `l op r` computed row by row.
MatrixHelper rowwiseOperator(const std::string& op, const BasicType& l, const BasicType& r, const BasicType& result);

// Whether `target op value` (op a compound assignment: `+=`, `<<=` ...) needs a helper.
bool needsRowwiseAssignment(const std::string& op, const BasicType& target, const BasicType& value);
// `T name(inout T a, V b)`: each row of a assigned its `op` with b's; a's new value returned.
MatrixHelper rowwiseAssignment(const std::string& op, const BasicType& target, const BasicType& value);

// Whether `-m`, `++m`, `m--` ... need a helper (an int or uint matrix).
bool needsRowwiseUnary(const BasicType& m);
MatrixHelper rowwiseNegation(const BasicType& m);
// `T name(inout T a)`: each row of a incremented (op `++`) or decremented (`--`); a's new value
// returned, or its old one for the postfix forms.
MatrixHelper rowwiseIncrement(const std::string& op, bool postfix, const BasicType& m);

}  // namespace fxport::xlate
