// See matrix_operators.h.
#include "rewrite/matrix_operators.h"

#include <map>

#include "hlsl/expression_types.h"

namespace fxport::xlate {

namespace {

// The operators fxc computes per component, and the names their helpers take.
const std::map<std::string, std::string> kOperatorNames = {
    {"+", "add"}, {"-", "sub"}, {"*", "mul"}, {"/", "div"}, {"%", "mod"}, {"&", "and"}, {"|", "or"}, {"^", "xor"},
    {"<<", "shl"}, {">>", "shr"}, {"==", "eq"}, {"!=", "ne"}, {"<", "lt"}, {">", "gt"}, {"<=", "le"}, {">=", "ge"}};

bool isComparison(const std::string& op) { return op == "==" || op == "!=" || op == "<" || op == ">" || op == "<=" || op == ">="; }
bool isFullMatrix(const BasicType& b) { return b.isMatrix && b.rows > 1 && b.columns > 1; }
bool isScalarLike(const BasicType& b) { return b.rows * b.columns == 1; }
bool isIntegral(const BasicType& b) {
    const std::string s = glslangScalar(b.scalar);
    return s != "float" && s != "double";
}
bool isIntegralMatrix(const BasicType& b) { return isFullMatrix(b) && isIntegral(b); }

// An operand the helpers take: a full matrix of the result's shape, or a scalar.
bool fits(const BasicType& operand, const BasicType& shape) {
    return isScalarLike(operand) || (isFullMatrix(operand) && operand.rows == shape.rows && operand.columns == shape.columns);
}

// glslang's row vector of `columns` components that computes an operation on `scalar` values:
// bool ones compute as int (fxc's bool arithmetic is int; a comparison of bools the same).
std::string rowType(const std::string& scalar, int columns) {
    std::string s = glslangScalar(scalar);
    if (s == "bool") s = "int";
    return s + std::to_string(columns);
}

// Row r of parameter `v` of type `type` as a `row` vector (a scalar fills it).
std::string rowOf(const BasicType& type, const std::string& v, int r, const std::string& row) {
    return row + "(" + v + (isScalarLike(type) ? "" : "[" + std::to_string(r) + "]") + ")";
}

}  // namespace

bool needsRowwiseOperator(const std::string& op, const BasicType& l, const BasicType& r, const BasicType& result) {
    if (!kOperatorNames.count(op) || !isFullMatrix(result) || !fits(l, result) || !fits(r, result)) return false;
    return isComparison(op) || (op == "*" && l.isMatrix && r.isMatrix) || isIntegralMatrix(l) || isIntegralMatrix(r);
}

MatrixHelper rowwiseOperator(const std::string& op, const BasicType& l, const BasicType& r, const BasicType& result) {
    const std::string name = "fxport_matrix_" + kOperatorNames.at(op) + "_" + glslangSpelling(l) + "_" + glslangSpelling(r);
    const std::string resultType = glslangSpelling(result), row = rowType(commonScalar(l.scalar, r.scalar), result.columns);
    std::string code = resultType + " " + name + "(" + glslangSpelling(l) + " a, " + glslangSpelling(r) + " b) { " + resultType + " r; ";
    for (int i = 0; i < result.rows; ++i)
        code += "r[" + std::to_string(i) + "] = " + rowOf(l, "a", i, row) + " " + op + " " + rowOf(r, "b", i, row) + "; ";
    return {name, code + "return r; } "};
}

bool needsRowwiseAssignment(const std::string& op, const BasicType& target, const BasicType& value) {
    const std::string binary = op.substr(0, op.size() - 1);
    if (!kOperatorNames.count(binary) || isComparison(binary) || !isFullMatrix(target) || !fits(value, target)) return false;
    return (binary == "*" && value.isMatrix) || isIntegralMatrix(target) || isIntegralMatrix(value);
}

MatrixHelper rowwiseAssignment(const std::string& op, const BasicType& target, const BasicType& value) {
    const std::string binary = op.substr(0, op.size() - 1);
    const std::string type = glslangSpelling(target);
    const std::string name = "fxport_matrix_" + kOperatorNames.at(binary) + "_assign_" + type + "_" + glslangSpelling(value);
    const std::string row = rowType(commonScalar(target.scalar, value.scalar), target.columns);
    BasicType targetRow = target;
    targetRow.isMatrix = false;
    targetRow.rows = 1;
    std::string code = type + " " + name + "(inout " + type + " a, " + glslangSpelling(value) + " b) { ";
    for (int i = 0; i < target.rows; ++i)  // fxc's `a op= b` is `a = (T)(a op b)`
        code += "a[" + std::to_string(i) + "] = " + glslangSpelling(targetRow) + "(" + rowOf(target, "a", i, row) + " " + binary + " " +
                rowOf(value, "b", i, row) + "); ";
    return {name, code + "return a; } "};
}

bool needsRowwiseUnary(const BasicType& m) {
    const std::string s = glslangScalar(m.scalar);
    return isFullMatrix(m) && (s == "int" || s == "uint");
}

MatrixHelper rowwiseNegation(const BasicType& m) {
    const std::string type = glslangSpelling(m), name = "fxport_matrix_negate_" + type;
    std::string code = type + " " + name + "(" + type + " a) { " + type + " r; ";
    for (int i = 0; i < m.rows; ++i) code += "r[" + std::to_string(i) + "] = -a[" + std::to_string(i) + "]; ";
    return {name, code + "return r; } "};
}

MatrixHelper rowwiseIncrement(const std::string& op, bool postfix, const BasicType& m) {
    const std::string type = glslangSpelling(m);
    const std::string name = std::string("fxport_matrix_") + (postfix ? "post" : "pre") + (op == "++" ? "increment_" : "decrement_") + type;
    std::string code = type + " " + name + "(inout " + type + " a) { " + (postfix ? type + " old = a; " : "");
    for (int i = 0; i < m.rows; ++i) code += "a[" + std::to_string(i) + "] " + op.substr(1) + "= 1; ";
    return {name, code + (postfix ? "return old; } " : "return a; } ")};
}

}  // namespace fxport::xlate
