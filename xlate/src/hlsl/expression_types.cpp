// See expression_types.h. A recursive-descent reading of one expression: each level returns the
// type or nothing, and nothing propagates up, so a half-understood expression has no type.
#include "hlsl/expression_types.h"

#include <algorithm>
#include <cstdlib>
#include <set>

#include "hlsl/variable_declarations.h"

namespace fxport::xlate {

namespace {

using Type = std::optional<ExpressionType>;

ExpressionType numeric(const BasicType& b) { return ExpressionType{b, {}, {}}; }

BasicType basic(const std::string& scalar, int rows, int columns, bool matrix) { return BasicType{scalar, rows, columns, matrix, true}; }

bool isScalarLike(const BasicType& b) { return b.rows * b.columns == 1; }
bool isDegenerate(const BasicType& b) { return b.isMatrix && (b.rows == 1 || b.columns == 1); }

// fxc's shape of an operation between a and b (both numeric), or nothing where fxc refuses it.
std::optional<BasicType> commonShape(const BasicType& a, const BasicType& b) {
    const std::string scalar = commonScalar(a.scalar, b.scalar);
    if (isScalarLike(a)) return basic(scalar, b.rows, b.columns, b.isMatrix);
    if (isScalarLike(b)) return basic(scalar, a.rows, a.columns, a.isMatrix);
    if (a.isMatrix && b.isMatrix) return basic(scalar, std::min(a.rows, b.rows), std::min(a.columns, b.columns), true);
    if (a.isMatrix != b.isMatrix) {
        const bool compatible = a.rows * a.columns == b.rows * b.columns || isDegenerate(a) || isDegenerate(b);
        if (!compatible) return std::nullopt;
    }
    const BasicType& smaller = a.rows * a.columns <= b.rows * b.columns ? a : b;
    return basic(scalar, smaller.rows, smaller.columns, smaller.isMatrix);
}

// Intrinsics whose result has their (first) argument's shape.
const std::set<std::string> kSameShapeFloat = {"abs", "saturate", "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh",
                                               "exp", "exp2", "log", "log2", "log10", "sqrt", "rsqrt", "frac", "floor", "ceil", "round",
                                               "trunc", "rcp", "radians", "degrees", "ddx", "ddy", "fwidth", "normalize", "reflect",
                                               "refract", "faceforward", "ddx_coarse", "ddy_coarse", "ddx_fine", "ddy_fine"};
const std::set<std::string> kElementwiseFloat = {"lerp", "smoothstep", "pow", "step", "atan2", "fmod", "ldexp"};
const std::set<std::string> kElementwise = {"clamp", "max", "min", "mad"};
const std::set<std::string> kScalarFloat = {"dot", "length", "distance", "determinant"};
const std::set<std::string> kTextureFetches = {"tex1D", "tex1Dlod", "tex1Dproj", "tex1Dbias", "tex1Dgrad", "tex2D", "tex2Dlod",
                                               "tex2Dproj", "tex2Dbias", "tex2Dgrad", "tex3D", "tex3Dlod", "tex3Dproj", "tex3Dbias",
                                               "tex3Dgrad", "texCUBE", "texCUBElod", "texCUBEproj", "texCUBEbias", "texCUBEgrad"};

class Reader {
public:
    Reader(const EffectSyntax& syntax, const FxFunction& f, size_t end) : syntax_(syntax), t_(syntax.tokens), f_(f), end_(end) {}

    ExpressionParts parts;

    Type whole(size_t begin) {
        at_ = begin;
        Type type = ternary();
        if (at_ != end_) return std::nullopt;
        return type;
    }

private:
    const EffectSyntax& syntax_;
    const std::vector<Token>& t_;
    const FxFunction& f_;
    size_t end_;
    size_t at_ = 0;
    int depth_ = 0;

    bool is(const char* s, size_t offset = 0) const { return at_ + offset < end_ && t_[at_ + offset].is(s); }

    // The binary operator at at_ (`<` `=` read as `<=`), its token count and precedence; 0 when none.
    int binaryOperator(std::string& op, size_t& width) const {
        if (at_ >= end_ || t_[at_].kind != Token::Kind::Punct) return 0;
        op = t_[at_].text;
        width = 1;
        if ((op == "<" || op == ">") && at_ + 1 < end_ && t_[at_ + 1].offset == t_[at_].end && (t_[at_ + 1].is("=") || t_[at_ + 1].is(op))) {
            op += t_[at_ + 1].text;
            width = 2;
            if (op == "<<" || op == ">>") {
                if (at_ + 2 < end_ && t_[at_ + 2].offset == t_[at_ + 1].end && t_[at_ + 2].is("=")) return 0;  // `<<=`
            }
        }
        static const std::pair<const char*, int> kPrecedence[] = {{"||", 1}, {"&&", 2}, {"|", 3},  {"^", 4},  {"&", 5},  {"==", 6},
                                                                  {"!=", 6}, {"<", 7},  {">", 7},  {"<=", 7}, {">=", 7}, {"<<", 8},
                                                                  {">>", 8}, {"+", 9},  {"-", 9},  {"*", 10}, {"/", 10}, {"%", 10}};
        for (const auto& [text, precedence] : kPrecedence)
            if (op == text) return precedence;
        return 0;
    }

    Type ternary() {
        if (++depth_ > 64) return std::nullopt;
        const size_t begin = at_;
        Type condition = binary(1);
        if (!condition || !is("?")) {
            --depth_;
            return condition;
        }
        const size_t question = at_++;
        Type a = ternary();
        if (!a || !is(":")) return std::nullopt;
        const size_t colon = at_++;
        Type b = ternary();
        --depth_;
        if (!b || !a->isNumeric() || !b->isNumeric()) return std::nullopt;
        auto shape = commonShape(a->basic, b->basic);
        if (!shape) return std::nullopt;
        // Scalar branches take a vector or matrix condition's shape: fxc selects per component
        // (vkd3d's add_ternary).
        const BasicType& c = condition->basic;
        if (isScalarLike(*shape) && condition->isNumeric() && !isScalarLike(c)) shape = basic(shape->scalar, c.rows, c.columns, c.isMatrix);
        ExpressionType out = withVector1(numeric(*shape), *a, *b);
        out.keptMatrix = a->keptMatrix || b->keptMatrix || condition->keptMatrix;
        parts.selections.push_back({begin, question, colon, at_, *condition, *a, *b, out});
        return out;
    }

    // A one-component operand takes the other's class (vkd3d's expr_common_shape).
    static ExpressionType withVector1(ExpressionType result, const ExpressionType& a, const ExpressionType& b) {
        if (isScalarLike(a.basic)) result.vector1 = b.vector1;
        else if (isScalarLike(b.basic)) result.vector1 = a.vector1;
        return result;
    }

    Type binary(int minPrecedence) {
        const size_t leftBegin = at_;
        Type left = unary();
        for (;;) {
            std::string op;
            size_t width = 0;
            const int precedence = binaryOperator(op, width);
            if (!left || precedence < minPrecedence || precedence == 0) return left;
            const size_t leftEnd = at_;
            at_ += width;
            const size_t rightBegin = at_;
            Type right = binary(precedence + 1);
            if (!right || !left->isNumeric() || !right->isNumeric()) return std::nullopt;
            auto shape = commonShape(left->basic, right->basic);
            if (!shape) return std::nullopt;
            const bool logical = precedence <= 2 || precedence == 6 || precedence == 7;
            if (logical) shape->scalar = "bool";
            else if (shape->scalar == "bool") shape->scalar = "int";
            const bool kept = left->keptMatrix || right->keptMatrix;
            parts.operations.push_back({leftBegin, leftEnd, rightBegin, at_, left->basic, right->basic, *shape, op, kept});
            left = withVector1(numeric(*shape), *left, *right);
            left->keptMatrix = kept;
        }
    }

    // `(T)`, `(T[2])`, `(struct S)` at at_: the type, at_ past ')'.
    Type cast() {
        size_t j = at_ + 1;
        if (j < end_ && t_[j].is("struct")) ++j;
        if (j >= end_ || !t_[j].isIdent()) return std::nullopt;
        Type type = typeNamed(t_[j].text);
        if (!type) return std::nullopt;
        for (++j; j + 2 < end_ && t_[j].is("[") && t_[j + 2].is("]"); j += 3) {
            if (t_[j + 1].kind != Token::Kind::Number) return std::nullopt;
            type->dims.push_back(std::atoi(t_[j + 1].text.c_str()));
        }
        if (j >= end_ || !t_[j].is(")")) return std::nullopt;
        at_ = j + 1;
        return type;
    }

    Type typeNamed(const std::string& name) const {
        const std::string& resolved = syntax_.resolveType(name);
        BasicType b = describeBasicType(resolved);
        if (b.ok) {
            ExpressionType type = numeric(b);
            std::string compact;
            for (char c : resolved)
                if (c != ' ') compact += c;
            type.vector1 = !b.isMatrix && b.columns == 1 && (compact.back() == '1' || (compact.size() > 3 && compact.compare(compact.size() - 3, 3, ",1>") == 0));
            return type;
        }
        if (!syntax_.findStruct(resolved)) return std::nullopt;
        // Built member by member: GCC 12 at -O3 takes the aggregate's string for uninitialised.
        ExpressionType type;
        type.structName = resolved;
        return type;
    }

    Type unary() {
        if (at_ >= end_) return std::nullopt;
        if (is("-")) {
            const size_t minus = at_++;
            Type operand = unary();
            if (operand && operand->isNumeric()) parts.negations.push_back({minus, at_, *operand});
            return operand;
        }
        if (is("+") || is("~") || is("++") || is("--")) {
            ++at_;
            return unary();
        }
        if (is("!")) {
            ++at_;
            Type operand = unary();
            if (operand && operand->isNumeric()) operand->basic.scalar = "bool";
            return operand;
        }
        if (is("(")) {
            const size_t open = at_;
            if (Type type = cast()) {
                Type operand = unary();
                if (!operand) return std::nullopt;
                return type;
            }
            at_ = open;
        }
        return postfix(primary());
    }

    Type postfix(Type type) {
        while (type && at_ < end_) {
            if (is("++") || is("--")) {
                ++at_;
            } else if (is("[")) {
                ++at_;
                Type index = ternary();
                if (!index || !is("]")) return std::nullopt;
                ++at_;
                type = element(*type);
            } else if (is(".") && at_ + 1 < end_ && t_[at_ + 1].isIdent()) {
                if (at_ + 2 < end_ && t_[at_ + 2].is("(")) return std::nullopt;  // a method
                type = member(*type, t_[at_ + 1].text);
                at_ += 2;
            } else {
                break;
            }
        }
        return type;
    }

    Type element(ExpressionType type) const {
        if (!type.dims.empty()) {
            type.dims.erase(type.dims.begin());
            return type;
        }
        if (!type.isNumeric()) return std::nullopt;
        BasicType& b = type.basic;
        if (b.isMatrix) return numeric(basic(b.scalar, 1, b.columns, false));
        if (b.columns > 1) return numeric(basic(b.scalar, 1, 1, false));
        return std::nullopt;
    }

    Type member(const ExpressionType& type, const std::string& name) const {
        if (!type.dims.empty()) return std::nullopt;
        if (const FxStruct* s = syntax_.findStruct(type.structName)) {
            for (const auto& m : s->members)
                if (m.name == name) {
                    Type t = typeNamed(m.type);
                    if (t) t->dims = m.arrayDims;
                    if (t) t->keptMatrix = isDegenerate(t->basic);
                    return t;
                }
            return std::nullopt;
        }
        if (!type.isNumeric()) return std::nullopt;
        int count = 0;
        if (type.basic.isMatrix) {  // _m01_m10 or _12_21
            for (size_t i = 0; i < name.size(); ++count) {
                if (name[i] != '_') return std::nullopt;
                i += name.compare(i, 2, "_m") == 0 ? 4 : 3;
                if (i > name.size()) return std::nullopt;
            }
        } else {
            const bool xyzw = name.find_first_not_of("xyzw") == std::string::npos, rgba = name.find_first_not_of("rgba") == std::string::npos;
            if (!xyzw && !rgba) return std::nullopt;
            count = static_cast<int>(name.size());
        }
        if (count < 1 || count > 4) return std::nullopt;
        return numeric(basic(type.basic.scalar, 1, count, false));
    }

    // The arguments of the call whose '(' is at at_, at_ past its ')'.
    std::optional<std::vector<ExpressionType>> arguments() {
        std::vector<ExpressionType> out;
        ++at_;
        if (is(")")) {
            ++at_;
            return out;
        }
        for (;;) {
            Type a = ternary();
            if (!a) return std::nullopt;
            out.push_back(*a);
            if (is(")")) break;
            if (!is(",")) return std::nullopt;
            ++at_;
        }
        ++at_;
        return out;
    }

    Type primary() {
        if (at_ >= end_) return std::nullopt;
        const Token& tk = t_[at_];
        if (tk.kind == Token::Kind::Number) {
            ++at_;
            return numeric(basic(literalScalar(tk.text), 1, 1, false));
        }
        if (tk.is("(")) {
            ++at_;
            Type inner = ternary();
            if (!inner || !is(")")) return std::nullopt;
            ++at_;
            return inner;
        }
        if (!tk.isIdent()) return std::nullopt;
        if (tk.is("true") || tk.is("false")) {
            ++at_;
            return numeric(basic("bool", 1, 1, false));
        }
        if (is("(", 1)) {
            const std::string& name = tk.text;
            ++at_;
            auto args = arguments();
            if (!args) return std::nullopt;
            if (Type constructed = typeNamed(name); constructed && constructed->isNumeric()) return constructed;
            return call(name, *args);
        }
        auto declared = declaredVariable(syntax_, f_, tk.text, at_);
        const size_t use = at_++;
        if (!declared) return std::nullopt;
        if (Type elements = structuredBufferOfStructs(declared->type)) return elements;
        Type type = typeNamed(declared->type);
        if (type) type->dims = declared->dims;
        if (type && isDegenerate(type->basic)) type->keptMatrix = !declaredLocally(tk.text, use);
        return type;
    }

    // `[RW]StructuredBuffer<S>` of a struct S: read as an array of S of no known size (dims {0}),
    // so that indexing gives an S (Intel AOIT assigns `B[i]` to a componentwise-equal array).
    // Buffers of numbers stay unknown: the rewrites that type numbers were not written for them.
    Type structuredBufferOfStructs(const std::string& declared) const {
        std::string compact;
        for (char c : declared)
            if (c != ' ' && c != '\t') compact += c;
        for (const char* prefix : {"StructuredBuffer<", "RWStructuredBuffer<"}) {
            const std::string p = prefix;
            if (compact.rfind(p, 0) != 0 || compact.back() != '>') continue;
            const std::string written = compact.substr(p.size(), compact.size() - p.size() - 1);
            const std::string element = syntax_.resolveType(written);
            if (!syntax_.findStruct(element)) return std::nullopt;
            ExpressionType type;
            type.structName = element;
            type.dims = {0};
            return type;
        }
        return std::nullopt;
    }

    // Whether `name` used at `use` is a local of the body or a parameter without a semantic (not
    // a uniform or an entry input).
    bool declaredLocally(const std::string& name, size_t use) const {
        for (size_t i = std::min(use, f_.body.end); i-- > f_.body.begin + 1;)
            if (t_[i].isIdent() && t_[i].text == name && t_[i - 1].isIdent() && !t_[i + 1].is("(") && typeNamed(t_[i - 1].text)) return true;
        for (const auto& p : f_.parameters)
            if (p.name == name) return p.semantic.empty();
        for (const auto& g : syntax_.globals)  // a static, or a uniform read as a vector (degenerate_matrices.h)
            if (g.name == name) return std::find(g.modifiers.begin(), g.modifiers.end(), "static") != g.modifiers.end() || isVectorUniform(syntax_, g);
        return false;
    }

    static std::string literalScalar(const std::string& text) {
        const bool hex = text.size() > 1 && text[0] == '0' && (text[1] == 'x' || text[1] == 'X');
        if (!hex && text.find_first_of(".eEfFhH") != std::string::npos) return "float";
        if (text.find_first_of("uU") != std::string::npos) return "uint";
        return "int";
    }

    Type call(const std::string& name, const std::vector<ExpressionType>& args) const {
        Type type = callType(name, args);
        if (type && !syntax_.findFunction(name))
            for (const auto& a : args) type->keptMatrix = type->keptMatrix || a.keptMatrix;
        return type;
    }

    Type callType(const std::string& name, const std::vector<ExpressionType>& args) const {
        if (syntax_.findFunction(name)) {
            std::optional<std::string> returned;
            for (const auto& fn : syntax_.functions) {
                if (fn.name != name || fn.parameters.size() != args.size()) continue;
                if (returned && *returned != fn.returnType) return std::nullopt;  // overloads: not evident
                returned = fn.returnType;
            }
            return returned ? typeNamed(*returned) : std::nullopt;
        }
        for (const auto& a : args)
            if (!a.isNumeric()) return std::nullopt;
        if (kTextureFetches.count(name)) return numeric(basic("float", 1, 4, false));
        if (args.empty()) return std::nullopt;
        const BasicType& first = args[0].basic;
        if (kSameShapeFloat.count(name)) {
            // fxc keeps half where every argument is half (refract(half4, half4, half) is a
            // half4, which an overload on half4 takes); any other mix computes in float.
            BasicType b = first;
            const bool allHalf = std::all_of(args.begin(), args.end(), [](const ExpressionType& a) { return a.basic.scalar == "half"; });
            if (name != "abs" && !allHalf) b.scalar = "float";
            return numeric(b);
        }
        if (name == "sign") return numeric(basic("int", first.rows, first.columns, first.isMatrix));
        if (kScalarFloat.count(name)) return numeric(basic("float", 1, 1, false));
        if (name == "all" || name == "any") return numeric(basic("bool", 1, 1, false));
        if (name == "cross") return numeric(basic("float", 1, 3, false));
        if (name == "transpose" && first.isMatrix) return numeric(basic(first.scalar, first.columns, first.rows, true));
        if (name == "asfloat" || name == "asint" || name == "asuint") {
            BasicType b = first;
            b.scalar = name.substr(2);
            return numeric(b);
        }
        if (name == "mul" && args.size() == 2) return productType(args[0], args[1]);
        if (kElementwise.count(name) || kElementwiseFloat.count(name)) {
            BasicType common = first;
            for (const auto& a : args) {
                auto shape = commonShape(common, a.basic);
                if (!shape) return std::nullopt;
                common = *shape;
            }
            if (kElementwiseFloat.count(name)) common.scalar = "float";
            return numeric(common);
        }
        return std::nullopt;
    }
};

}  // namespace

std::optional<ExpressionType> expressionType(const EffectSyntax& syntax, const FxFunction& f, size_t begin, size_t end,
                                             ExpressionParts* parts) {
    if (begin >= end || end > syntax.tokens.size()) return std::nullopt;
    Reader reader(syntax, f, end);
    Type type = reader.whole(begin);
    if (type && parts) *parts = std::move(reader.parts);
    return type;
}

ExpressionType productType(const ExpressionType& a, const ExpressionType& b) {
    const std::string scalar = commonScalar(a.basic.scalar, b.basic.scalar);
    const bool aScalar = !a.basic.isMatrix && !a.vector1 && a.basic.columns == 1, bScalar = !b.basic.isMatrix && !b.vector1 && b.basic.columns == 1;
    if (aScalar || bScalar) {
        const ExpressionType& other = aScalar ? b : a;
        ExpressionType out = numeric(basic(scalar, other.basic.rows, other.basic.columns, other.basic.isMatrix));
        out.vector1 = other.vector1;
        return out;
    }
    const int rows = a.basic.isMatrix ? a.basic.rows : 1, columns = b.basic.isMatrix ? b.basic.columns : 1;
    const int vectors = int(!a.basic.isMatrix) + int(!b.basic.isMatrix);
    if (vectors == 2) return numeric(basic(scalar, 1, 1, false));
    if (vectors == 1) {
        ExpressionType out = numeric(basic(scalar, 1, rows * columns, false));
        out.vector1 = rows * columns == 1;
        return out;
    }
    return numeric(basic(scalar, rows, columns, true));
}

std::string spellType(const BasicType& b) {
    if (b.isMatrix) return b.scalar + std::to_string(b.rows) + "x" + std::to_string(b.columns);
    return b.columns > 1 ? b.scalar + std::to_string(b.columns) : b.scalar;
}

std::string glslangScalar(const std::string& s) {
    if (s == "half" || s.rfind("min16f", 0) == 0 || s.rfind("min10f", 0) == 0) return "float";
    if (s == "dword" || s == "min16uint") return "uint";
    if (s.rfind("min", 0) == 0) return "int";
    return s;
}

std::string glslangSpelling(BasicType b) {
    b.scalar = glslangScalar(b.scalar);
    const int n = b.rows * b.columns;
    if (b.isMatrix && b.rows > 1 && b.columns > 1) return spellType(b);
    return n > 1 ? b.scalar + std::to_string(n) : b.scalar;
}

std::string commonScalar(const std::string& a, const std::string& b) {
    if (a == b) return a;
    auto rank = [](const std::string& s) {
        if (s == "double") return 4;
        if (s == "float" || s == "half" || s.rfind("min16f", 0) == 0 || s.rfind("min10f", 0) == 0) return 3;
        if (s == "uint" || s == "dword" || s == "min16uint") return 2;
        return 1;  // int, bool, min16int, min12int
    };
    static const char* const kNames[] = {"", "int", "uint", "float", "double"};
    return kNames[std::max(rank(a), rank(b))];
}

}  // namespace fxport::xlate
