// See mixed_shapes.h.
#include "rewrite/mixed_shapes.h"

#include <algorithm>
#include <functional>
#include <map>
#include <optional>
#include <set>
#include <string>

#include "hlsl/call_arguments.h"
#include "hlsl/expression_types.h"
#include "rewrite/matrix_operators.h"

namespace fxport::xlate {

namespace {

const std::set<std::string> kElementwise = {"clamp", "max", "min", "mad"};
const std::set<std::string> kElementwiseFloat = {"lerp", "smoothstep", "pow", "step", "fmod", "ldexp"};

// Component (r, c) of `v`, a value of fxc type `from` as glslang holds it.
std::string component(const BasicType& from, int r, int c, const std::string& v = "v") {
    const int n = from.rows * from.columns;
    if (n == 1) return v;
    if (!from.isMatrix || from.rows == 1 || from.columns == 1) return v + "[" + std::to_string(r * from.columns + c) + "]";
    return v + "[" + std::to_string(r) + "][" + std::to_string(c) + "]";
}

std::string shapeName(const ExpressionType& e) { return spellType(e.basic) + (e.vector1 ? "1" : ""); }

// Whether mul(a, b) needs fxc's meaning spelled out: a one-component vector or matrix, or a
// one-row or one-column matrix, takes part (glslang crashes on the first, and holds the others as
// vectors, which mul would take as rows or columns where fxc does not); plain scalars, vectors
// and full float matrices glslang multiplies as fxc does.
bool mulNeedsHelper(const ExpressionType& a, const ExpressionType& b) {
    auto scalar = [](const ExpressionType& e) { return !e.basic.isMatrix && !e.vector1 && e.basic.columns == 1; };
    if (scalar(a) || scalar(b)) return false;
    auto odd = [](const ExpressionType& e) { return e.vector1 || (e.basic.isMatrix && (e.basic.rows == 1 || e.basic.columns == 1)); };
    // An int, uint or bool matrix: glslang has no overload of mul for one (GLSL has no integer
    // matrices); fxc multiplies in the common component type (vkd3d's minimum-precision L5).
    auto integer = [](const ExpressionType& e) { return e.basic.isMatrix && glslangScalar(e.basic.scalar) != "float" && e.basic.scalar != "double"; };
    return odd(a) || odd(b) || integer(a) || integer(b);
}

// `R name(A a, B b) { return R(sums); }`: fxc's mul, a vector a row on the left and a column on
// the right, over the smaller inner dimension.
std::string mulCode(const std::string& name, const ExpressionType& a, const ExpressionType& b) {
    BasicType result = productType(a, b).basic;
    const int rows = a.basic.isMatrix ? a.basic.rows : 1, columns = b.basic.isMatrix ? b.basic.columns : 1;
    const int inner = std::min(a.basic.columns, b.basic.isMatrix ? b.basic.rows : b.basic.columns);
    auto of = [](const ExpressionType& e, const char* v, int r, int c, int k) {
        return e.basic.isMatrix ? component(e.basic, r, c, v) : component(e.basic, 0, k, v);
    };
    std::string text = glslangSpelling(result) + " " + name + "(" + glslangSpelling(a.basic) + " a, " + glslangSpelling(b.basic) + " b) { return " +
                       glslangSpelling(result) + "(";
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < columns; ++i) {
            text += j || i ? ", " : "";
            for (int k = 0; k < inner; ++k) text += std::string(k ? " + " : "") + of(a, "a", j, k, k) + " * " + of(b, "b", k, i, k);
        }
    return text + "); } ";
}

std::string helperName(const BasicType& from, const BasicType& to) {
    return "fxport_shape_" + glslangScalar(from.scalar) + spellType(from).substr(from.scalar.size()) + "_to_" + glslangScalar(to.scalar) +
           spellType(to).substr(to.scalar.size());
}

// `to helper(from v) { return to(components); }`: a scalar fills every component; a matrix gives
// its top-left rows and columns.
std::string helperCode(const BasicType& from, const BasicType& to) {
    std::string text = glslangSpelling(to) + " " + helperName(from, to) + "(" + glslangSpelling(from) + " v) { return " + glslangSpelling(to) + "(";
    for (int r = 0; r < to.rows; ++r)
        for (int c = 0; c < to.columns; ++c) text += std::string(r || c ? ", " : "") + component(from, r, c);
    return text + "); } ";
}

// `T name(T a0, T a1 ...) { return T(intrinsic(a0[0], a1[0] ...), ...); }` for a matrix type T.
std::string rowwiseCode(const std::string& intrinsic, const std::string& name, const BasicType& type, size_t arguments) {
    const std::string spelled = spellType(type);
    std::string text = spelled + " " + name + "(";
    for (size_t a = 0; a < arguments; ++a) text += (a ? ", " : "") + spelled + " a" + std::to_string(a);
    text += ") { return " + spelled + "(";
    for (int r = 0; r < type.rows; ++r) {
        text += (r ? ", " : "") + intrinsic + "(";
        for (size_t a = 0; a < arguments; ++a) text += (a ? ", a" : "a") + std::to_string(a) + "[" + std::to_string(r) + "]";
        text += ")";
    }
    return text + "); } ";
}

bool isDegenerateMatrix(const BasicType& b) { return b.isMatrix && (b.rows == 1 || b.columns == 1); }

bool sameType(const BasicType& a, const BasicType& b) {
    return glslangSpelling(a) == glslangSpelling(b) && a.isMatrix == b.isMatrix;
}


// fxc's common type of an element-wise call's arguments, when a matrix takes part and no vector.
std::optional<BasicType> commonMatrixType(const std::vector<BasicType>& args, bool floatOnly) {
    bool matrix = false;
    BasicType common{args[0].scalar, 4, 4, true, true};
    for (const BasicType& a : args) {
        common.scalar = commonScalar(common.scalar, a.scalar);
        if (a.isMatrix) {
            matrix = true;
            common.rows = std::min(common.rows, a.rows);
            common.columns = std::min(common.columns, a.columns);
        } else if (a.columns > 1) {
            return std::nullopt;  // a vector with a matrix: fxc refuses it, glslang too
        }
    }
    if (!matrix) return std::nullopt;
    if (floatOnly || common.scalar == "half") common.scalar = "float";
    if (common.scalar == "bool") common.scalar = "int";
    return common;
}

// The arguments' types of `mul(a, b)` at token i when its product needs a helper.
std::optional<std::pair<ExpressionType, ExpressionType>> mulArguments(const EffectSyntax& syntax, const FxFunction& f, size_t i) {
    const auto& t = syntax.tokens;
    if (!t[i].is("mul") || !t[i + 1].is("(") || (i > 0 && t[i - 1].is(".")) || syntax.findFunction("mul")) return std::nullopt;
    auto spans = callArgumentSpans(t, i + 1, f.body.end);
    if (spans.size() != 2) return std::nullopt;
    auto a = expressionType(syntax, f, spans[0].first, spans[0].second), b = expressionType(syntax, f, spans[1].first, spans[1].second);
    if (!a || !b || !a->isNumeric() || !b->isNumeric() || a->keptMatrix || b->keptMatrix || !mulNeedsHelper(*a, *b)) return std::nullopt;
    return std::make_pair(*a, *b);
}

class MixedShapes {
public:
    explicit MixedShapes(const EffectSyntax& syntax) : syntax_(syntax), t_(syntax.tokens) {}

    std::vector<TextEdit> run() {
        for (const auto& f : syntax_.functions) {
            for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
                call(f, i);
                mul(f, i);
                matrixIntrinsic(f, i);
                compoundAssignment(f, i);
                increment(f, i);
                if (size_t e = expressionAfter(f, i)) operators(f, i + 1, e);
                groupedExpressions(f, i);
            }
        }
        insertConversions();
        if (helpers_.empty()) return std::move(edits_);
        size_t first = syntax_.functions.front().declaration.begin;
        for (const auto& f : syntax_.functions) first = std::min(first, f.declaration.begin);
        std::string code;
        for (const auto& [name, text] : helpers_) code += text;
        edits_.push_back({t_[first].offset, t_[first].offset, code});
        return std::move(edits_);
    }

private:
    const EffectSyntax& syntax_;
    const std::vector<Token>& t_;
    std::vector<TextEdit> edits_;
    std::map<std::string, std::string> helpers_;  // name -> code
    std::set<std::pair<size_t, size_t>> converted_;  // token spans already passed through a helper
    // Helper calls opened before a token (widest span first) and closed after one.
    std::map<size_t, std::multimap<size_t, std::string, std::greater<size_t>>> opened_;
    std::map<size_t, int> closed_;
    std::set<size_t> selected_;  // first tokens of selections already spelled out
    std::set<std::pair<size_t, size_t>> wrapped_;  // token spans already passed to a matrix_operators.h helper

    // Tokens [b, e), of type `from`, passed through the helper that makes them `to`.
    void convert(size_t b, size_t e, const BasicType& from, const BasicType& to) {
        if (!converted_.insert({b, e}).second) return;
        const std::string name = helperName(from, to);
        helpers_.emplace(name, helperCode(from, to));
        opened_[b].emplace(e - b, name + "(");
        ++closed_[e - 1];
    }

    // One insertion per place, so nested helper calls open and close in order.
    void insertConversions() {
        for (const auto& [token, names] : opened_) {
            std::string text;
            for (const auto& [width, name] : names) text += name;
            edits_.push_back({t_[token].offset, t_[token].offset, text});
        }
        for (const auto& [token, count] : closed_) edits_.push_back({t_[token].end, t_[token].end, std::string(size_t(count), ')')});
    }

    // mul(a, b) at i, where glslang would not compute fxc's product.
    void mul(const FxFunction& f, size_t i) {
        auto types = mulArguments(syntax_, f, i);
        if (!types) return;
        const std::string name = "fxport_mul_" + shapeName(types->first) + "_" + shapeName(types->second);
        helpers_.emplace(name, mulCode(name, types->first, types->second));
        edits_.push_back({t_[i].offset, t_[i].end, name});
    }

    // determinant of a matrix that is not square: fxc takes its top-left square (float3x4: the
    // 3x3, float2x1: the one component); transpose of a one-row or one-column matrix: the same
    // components, and the same vector to glslang. glslang has neither overload.
    void matrixIntrinsic(const FxFunction& f, size_t i) {
        const bool determinant = t_[i].is("determinant");
        if ((!determinant && !t_[i].is("transpose")) || !t_[i + 1].is("(") || (i > 0 && t_[i - 1].is(".")) || syntax_.findFunction(t_[i].text)) return;
        auto spans = callArgumentSpans(t_, i + 1, f.body.end);
        if (spans.size() != 1) return;
        auto type = expressionType(syntax_, f, spans[0].first, spans[0].second);
        if (!type || !type->isNumeric() || type->keptMatrix || !type->basic.isMatrix) return;
        const BasicType& m = type->basic;
        if (!determinant) {
            if (isDegenerateMatrix(m) && m.rows * m.columns > 1) edits_.push_back({t_[i].offset, t_[i].end, ""});
            return;
        }
        if (m.rows == m.columns) return;
        const int n = std::min(m.rows, m.columns);
        const std::string name = "fxport_determinant_" + spellType(m);
        std::string code = "float " + name + "(" + glslangSpelling(m) + " v) { return ";
        if (n == 1) {
            code += component(m, 0, 0);
        } else {
            code += "determinant(float" + std::to_string(n) + "x" + std::to_string(n) + "(";
            for (int r = 0; r < n; ++r)
                for (int c = 0; c < n; ++c) code += std::string(r || c ? ", " : "") + component(m, r, c);
            code += "))";
        }
        helpers_.emplace(name, code + "; } ");
        edits_.push_back({t_[i].offset, t_[i].end, name});
    }

    // An element-wise intrinsic's call at i.
    void call(const FxFunction& f, size_t i) {
        if (!t_[i].isIdent() || !t_[i + 1].is("(") || (i > 0 && t_[i - 1].is("."))) return;
        const bool floatOnly = kElementwiseFloat.count(t_[i].text) > 0;
        if ((!floatOnly && !kElementwise.count(t_[i].text)) || syntax_.findFunction(t_[i].text)) return;
        auto spans = callArgumentSpans(t_, i + 1, f.body.end);
        if (spans.size() < 2) return;
        std::vector<BasicType> types;
        for (const auto& [b, e] : spans) {
            auto type = expressionType(syntax_, f, b, e);
            if (!type || !type->isNumeric() || type->keptMatrix) return;
            types.push_back(type->basic);
        }
        auto common = commonMatrixType(types, floatOnly);
        if (!common) return;
        if (common->rows > 1 && common->columns > 1) {
            // glslang crashes on some intrinsics of matrices and SPIRV-Cross writes GLSL
            // (clamp(mat2, ...)) no driver takes: one call per row instead.
            const std::string name = "fxport_" + t_[i].text + "_" + spellType(*common);
            helpers_.emplace(name, rowwiseCode(t_[i].text, name, *common, spans.size()));
            edits_.push_back({t_[i].offset, t_[i].end, name});
        }
        for (size_t a = 0; a < spans.size(); ++a)
            if (!sameType(types[a], *common)) convert(spans[a].first, spans[a].second, types[a], *common);
    }

    // The end of the expression that follows token i when i is `return` or an assignment's
    // (compound or not) or initializer's `=`: the `;` or `,` that ends it, or the `)` around it (a
    // `for` header's step, `(x = a * b)`); 0 when i starts none.
    size_t expressionAfter(const FxFunction& f, size_t i) const {
        if (!t_[i].is("return") && !t_[i].is("=") && compoundWidth(i) != 1) return 0;  // `<<=` is read at its `=`
        if (t_[i].is("=") && i > 0 && adjacent(i - 1) && (t_[i - 1].is("<") || t_[i - 1].is(">")) &&
            !(i > 1 && adjacent(i - 2) && t_[i - 2].is(t_[i - 1].text)))
            return 0;  // `<=`, `>=`; `<<=`, `>>=` are assignments
        int depth = 0;
        for (size_t j = i + 1; j < f.body.end; ++j) {
            if (t_[j].is("(") || t_[j].is("[") || t_[j].is("{")) ++depth;
            else if ((t_[j].is(")") || t_[j].is("]") || t_[j].is("}")) && --depth < 0) return t_[j].is(")") && j > i + 1 ? j : 0;
            else if (depth == 0 && (t_[j].is(";") || t_[j].is(","))) return j > i + 1 ? j : 0;
        }
        return 0;
    }

    // Each part of the bracket group that opens at i, `(` or `[`: a condition, a `for` header's
    // parts, a call's or a method's arguments, an index, a parenthesised operand. A whole
    // expression has no type when any of it is beyond the typer (a method call: `T.Sample(s,
    // (a * b)[1])`), so its parts are read on their own too; the type of a part is the same
    // wherever it stands, and every helper is placed once per span.
    void groupedExpressions(const FxFunction& f, size_t i) {
        if (!t_[i].is("(") && !t_[i].is("[")) return;
        int depth = 0;
        size_t begin = i + 1;
        for (size_t j = i + 1; j < f.body.end; ++j) {
            if (t_[j].is("(") || t_[j].is("[") || t_[j].is("{")) {
                ++depth;
            } else if (t_[j].is(")") || t_[j].is("]") || t_[j].is("}")) {
                if (--depth >= 0) continue;
                if (j > begin) operators(f, begin, j);
                return;
            } else if (depth == 0 && (t_[j].is(",") || t_[j].is(";"))) {
                if (j > begin) operators(f, begin, j);
                begin = j + 1;
            }
        }
    }

    // Whether token i ends where token i + 1 starts.
    bool adjacent(size_t i) const { return t_[i].end == t_[i + 1].offset; }

    // The tokens of the compound assignment that starts at i (`+=`: 1, `<` `<` `=`: 3); 0 when none.
    size_t compoundWidth(size_t i) const {
        static const std::set<std::string> kCompound = {"+=", "-=", "*=", "/=", "%=", "&=", "|=", "^="};
        if (kCompound.count(t_[i].text) && t_[i].kind == Token::Kind::Punct) return 1;
        const bool shift = (t_[i].is("<") || t_[i].is(">")) && i + 2 < t_.size() && t_[i + 1].is(t_[i].text) && t_[i + 2].is("=");
        return shift && adjacent(i) && adjacent(i + 1) ? 3 : 0;
    }

    // The first token of the assignment target that ends before token i: a name, with member
    // selections and indexing (`a[i].m[2]`); 0 when there is none.
    size_t targetBefore(const FxFunction& f, size_t i) const {
        size_t j = i;
        for (;;) {
            if (j <= f.body.begin + 1) return 0;
            if (t_[j - 1].is("]")) {
                int depth = 0;
                do {
                    --j;
                    if (t_[j].is("]")) ++depth;
                    else if (t_[j].is("[")) --depth;
                } while (depth > 0 && j > f.body.begin + 1);
                if (depth != 0) return 0;
                continue;
            }
            if (!t_[j - 1].isIdent()) return j == i ? 0 : j;
            --j;
            if (!t_[j - 1].is(".")) return j;
            --j;
        }
    }

    // `target op= value` at i where fxc's per-component meaning needs spelling out
    // (matrix_operators.h): a helper takes the target inout.
    void compoundAssignment(const FxFunction& f, size_t i) {
        const size_t width = compoundWidth(i), valueEnd = width ? expressionAfter(f, i + width - 1) : 0;
        const size_t targetBegin = valueEnd ? targetBefore(f, i) : 0;
        if (!targetBegin) return;
        auto target = expressionType(syntax_, f, targetBegin, i), value = expressionType(syntax_, f, i + width, valueEnd);
        if (!target || !value || !target->isNumeric() || !value->isNumeric() || target->keptMatrix || value->keptMatrix) return;
        std::string op;
        for (size_t k = i; k < i + width; ++k) op += t_[k].text;
        if (!needsRowwiseAssignment(op, target->basic, value->basic)) return;
        wrap(rowwiseAssignment(op, target->basic, value->basic), targetBegin, i, i + width, valueEnd);
    }

    // The end of the assignment target that starts at token i: a name, with member selections
    // and indexing; 0 when there is none.
    size_t targetAfter(const FxFunction& f, size_t i) const {
        if (i >= f.body.end || !t_[i].isIdent()) return 0;
        size_t j = i + 1;
        while (j < f.body.end) {
            if (t_[j].is(".") && j + 1 < f.body.end && t_[j + 1].isIdent()) {
                j += 2;
            } else if (t_[j].is("[")) {
                int depth = 0;
                do {
                    if (t_[j].is("[")) ++depth;
                    else if (t_[j].is("]")) --depth;
                    ++j;
                } while (depth > 0 && j < f.body.end);
                if (depth != 0) return 0;
            } else {
                break;
            }
        }
        return j;
    }

    // `m++`, `--m` ... at i on an int or uint matrix (matrix_operators.h): a helper takes m inout.
    void increment(const FxFunction& f, size_t i) {
        if (!t_[i].is("++") && !t_[i].is("--")) return;
        const size_t before = targetBefore(f, i), after = before ? 0 : targetAfter(f, i + 1);
        const size_t begin = before ? before : i + 1, end = before ? i : after;
        if (!end) return;
        auto type = expressionType(syntax_, f, begin, end);
        if (!type || !type->isNumeric() || type->keptMatrix || !needsRowwiseUnary(type->basic)) return;
        const MatrixHelper helper = rowwiseIncrement(t_[i].text, before != 0, type->basic);
        helpers_.emplace(helper.name, helper.code);
        const size_t first = std::min(begin, i), last = std::max(end - 1, i);
        opened_[first].emplace(last + 1 - first, helper.name + "(");
        ++closed_[last];
        edits_.push_back({t_[i].offset, t_[i].end, ""});
    }

    // `helper(left, right)` in place of tokens [begin, end) whose operator is [op, opEnd).
    void wrap(const MatrixHelper& helper, size_t begin, size_t op, size_t opEnd, size_t end) {
        if (!wrapped_.insert({begin, end}).second) return;
        helpers_.emplace(helper.name, helper.code);
        opened_[begin].emplace(end - begin, helper.name + "(");
        ++closed_[end - 1];
        edits_.push_back({t_[op].offset, t_[opEnd - 1].end, ","});
    }

    // `-m` of an int or uint matrix (matrix_operators.h).
    void negate(const Negation& n) {
        if (n.operand.keptMatrix || !needsRowwiseUnary(n.operand.basic) || !wrapped_.insert({n.minus, n.end}).second) return;
        const MatrixHelper helper = rowwiseNegation(n.operand.basic);
        helpers_.emplace(helper.name, helper.code);
        opened_[n.minus + 1].emplace(n.end - n.minus - 1, helper.name + "(");
        ++closed_[n.end - 1];
        edits_.push_back({t_[n.minus].offset, t_[n.minus].end, ""});
    }

    // `c ? a : b` with a matrix condition of the result's shape: fxc selects component by
    // component; glslang takes a scalar condition only. A helper selects each component.
    void select(const Selection& s) {
        const BasicType &c = s.condition.basic, &r = s.result.basic;
        if (s.result.keptMatrix || !c.isMatrix || !r.isMatrix || c.rows != r.rows || c.columns != r.columns || c.rows * c.columns == 1) return;
        if (!selected_.insert(s.begin).second) return;
        // Each branch as it is (glslang converts no matrix argument to the result's type); the
        // result's constructor converts each component.
        const BasicType &a = s.first.basic, &b = s.second.basic;
        const std::string name = "fxport_select_" + glslangSpelling(c) + "_" + glslangSpelling(a) + "_" + glslangSpelling(b) + "_to_" + glslangSpelling(r);
        std::string code = glslangSpelling(r) + " " + name + "(" + glslangSpelling(c) + " c, " + glslangSpelling(a) + " a, " + glslangSpelling(b) +
                           " b) { return " + glslangSpelling(r) + "(";
        for (int i = 0; i < r.rows; ++i)
            for (int k = 0; k < r.columns; ++k)
                code += std::string(i || k ? ", " : "") + "(" + component(c, i, k, "c") + " != 0 ? " + component(a, i, k, "a") + " : " + component(b, i, k, "b") + ")";
        helpers_.emplace(name, code + "); } ");
        opened_[s.begin].emplace(s.end - s.begin, name + "(");
        ++closed_[s.end - 1];
        edits_.push_back({t_[s.question].offset, t_[s.question].end, ","});
        edits_.push_back({t_[s.colon].offset, t_[s.colon].end, ","});
    }

    // Binary operations between matrices of different shapes in tokens [b, e): fxc computes them
    // in the smaller rows and columns (float1x4 + float4x4 adds the first row); glslang refuses
    // them ("Could not perform requested binary operation"). Operations on matrices glslang
    // computes otherwise than fxc (matrix_operators.h) become helpers too.
    void operators(const FxFunction& f, size_t b, size_t e) {
        ExpressionParts parts;
        if (!expressionType(syntax_, f, b, e, &parts)) return;
        for (const auto& s : parts.selections) select(s);
        for (const auto& n : parts.negations) negate(n);
        for (const auto& op : parts.operations) {
            if (op.keptMatrix) continue;
            BasicType lTo = op.left, rTo = op.right;
            if (op.left.isMatrix && op.right.isMatrix && (op.left.rows != op.right.rows || op.left.columns != op.right.columns)) {
                lTo.rows = rTo.rows = std::min(op.left.rows, op.right.rows);
                lTo.columns = rTo.columns = std::min(op.left.columns, op.right.columns);
                if (!sameType(op.left, lTo)) convert(op.leftBegin, op.leftEnd, op.left, lTo);
                if (!sameType(op.right, rTo)) convert(op.rightBegin, op.rightEnd, op.right, rTo);
            }
            if (needsRowwiseOperator(op.op, lTo, rTo, op.result))
                wrap(rowwiseOperator(op.op, lTo, rTo, op.result), op.leftBegin, op.leftEnd, op.rightBegin, op.rightEnd);
        }
    }
};

}  // namespace

std::vector<TextEdit> mixedShapeConversions(const EffectSyntax& syntax) { return MixedShapes(syntax).run(); }

std::set<size_t> mulCallsSpelledOut(const EffectSyntax& syntax) {
    std::set<size_t> out;
    for (const auto& f : syntax.functions)
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i)
            if (mulArguments(syntax, f, i)) out.insert(i);
    return out;
}

}  // namespace fxport::xlate
