// See aggregate_conversions.h.
#include "rewrite/aggregate_conversions.h"

#include <algorithm>
#include <cctype>
#include <optional>
#include <set>
#include <string>

#include "hlsl/aggregate_components.h"
#include "hlsl/expression_types.h"
#include "hlsl/hlsl_types.h"
#include "hlsl/variable_declarations.h"

namespace fxport::xlate {

namespace {

std::string identifierPart(const std::string& text) {
    std::string out;
    for (char c : text) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return out;
}

std::string dimsSpelled(const std::vector<int>& dims) {
    std::string out;
    for (int d : dims) out += "[" + std::to_string(d) + "]";
    return out;
}

bool isBoundary(const Token& t) { return t.is(";") || t.is("{") || t.is("}"); }

class Conversions {
public:
    explicit Conversions(const EffectSyntax& syntax) : syntax_(syntax), t_(syntax.tokens) {}

    void in(const FxFunction& f) {
        for (size_t i = f.body.begin; i + 2 < f.body.end; ++i) {
            returned(f, i);
            declared(f, i);
            assigned(f, i);
            cast(f, i);
            passed(f, i);
        }
    }
    std::vector<TextEdit> edits;

private:
    // `return e;`: to the function's return type.
    void returned(const FxFunction& f, size_t i) {
        if (!t_[i].is("return") || t_[i + 1].is(";")) return;
        const size_t end = expressionEnd(f, i + 1);
        if (t_[end].is(";")) convertInPlace(f, i + 1, end, {f.returnType, {}}, false, i + 1);
    }
    // `[const] T y[N]... = e;` at a statement's start, T a struct or y an array (a static's
    // initializer is no place for a call). A struct is initialized from the converting function's
    // value; an array, which no function returns, is declared and then filled by the function
    // (not a const one then).
    void declared(const FxFunction& f, size_t i) {
        if (!t_[i].isIdent() || !t_[i + 1].isIdent() || t_[i].is("return")) return;
        DeclaredVariable to{t_[i].text, {}};
        size_t equals = i + 2;
        for (; equals + 2 < f.body.end && t_[equals].is("[") && t_[equals + 2].is("]"); equals += 3) {
            if (t_[equals + 1].kind != Token::Kind::Number) return;
            to.dims.push_back(std::atoi(t_[equals + 1].text.c_str()));
        }
        if (!t_[equals].is("=") || t_[equals + 1].is("{")) return;
        bool isConst = false;
        size_t start = i;
        for (; start > f.body.begin && !isBoundary(t_[start - 1]); --start) {
            if (t_[start - 1].is("static") || t_[start - 1].is("else") || !t_[start - 1].isIdent()) return;
            isConst = isConst || t_[start - 1].is("const");
        }
        const size_t end = expressionEnd(f, equals + 1);
        if (!t_[end].is(";")) return;  // `T a = x, b = y;`: glslang's
        if (to.dims.empty()) {
            convertInPlace(f, equals + 1, end, to, false, equals + 1);
            return;
        }
        if (isConst) return;
        const std::string name = define(f, equals + 1, end, to);
        if (name.empty()) return;
        edits.push_back({t_[equals].offset, t_[equals].end, "; " + name + "(" + t_[i + 1].text + ","});
        edits.push_back({t_[end - 1].end, t_[end - 1].end, ")"});
    }
    // `y = e;` as a statement, y an lvalue of a struct or array type (a variable, a member, a
    // structured buffer's element): a struct is assigned the converting function's value; an
    // array is the function's out argument (`fxport_convert_C_to_uint4_1(d.color, B[0]);`), so y
    // and e are each evaluated once, y first as fxc does.
    void assigned(const FxFunction& f, size_t i) {
        if (!startsStatement(f, i) || !t_[i].isIdent() || t_[i].is("return")) return;
        size_t equals = 0;
        int depth = 0;
        for (size_t k = i; k < f.body.end && !(depth == 0 && t_[k].is(";")); ++k) {
            if (t_[k].is("(") || t_[k].is("[") || t_[k].is("{")) ++depth;
            if (t_[k].is(")") || t_[k].is("]") || t_[k].is("}")) --depth;
            if (depth < 0) return;
            if (depth == 0 && t_[k].is("=")) {
                equals = k;
                break;
            }
        }
        if (equals == 0) return;
        const size_t end = expressionEnd(f, equals + 1);
        auto to = typeOf(f, i, equals);
        if (!t_[end].is(";") || !to) return;
        if (to->dims.empty()) {
            convertInPlace(f, equals + 1, end, *to, false, equals + 1);
            return;
        }
        const std::string name = define(f, equals + 1, end, *to);
        if (name.empty()) return;
        edits.push_back({t_[i].offset, t_[i].offset, name + "("});
        edits.push_back({t_[equals].offset, t_[equals].end, ","});
        edits.push_back({t_[end - 1].end, t_[end - 1].end, ")"});
    }
    // `(T) x` of a struct T in an expression; `y = (T) x;` alone is componentwise_casts.h's. The
    // operand is what a cast binds: a postfix expression (`v`, `s.m[1]`, `float2(a, b)`, `f(x).v`)
    // or a parenthesised one.
    void cast(const FxFunction& f, size_t i) {
        size_t j = i + 1;
        if (!t_[i].is("(") || (t_[i - 1].isIdent() && !t_[i - 1].is("return"))) return;
        if (t_[j].is("struct")) ++j;
        if (j + 2 >= f.body.end || !t_[j].isIdent() || !t_[j + 1].is(")") || !(t_[j + 2].isIdent() || t_[j + 2].is("("))) return;
        const size_t x = j + 2;
        const size_t end = operandEnd(f, x);
        if (end <= x) return;
        if (end == x + 1 && t_[i - 1].is("=") && t_[i - 2].isIdent() && isBoundary(t_[i - 3]) && t_[x + 1].is(";")) return;
        convertInPlace(f, x, end, {t_[j].text, {}}, true, i);
    }
    // One past the postfix (or parenthesised) expression starting at x; x where there is none.
    size_t operandEnd(const FxFunction& f, size_t x) const {
        auto closing = [&](size_t open) {  // one past the bracket closing the one at `open`; 0 if none
            int depth = 0;
            for (size_t k = open; k < f.body.end; ++k) {
                if (t_[k].is("(") || t_[k].is("[")) ++depth;
                if ((t_[k].is(")") || t_[k].is("]")) && --depth == 0) return k + 1;
            }
            return size_t(0);
        };
        size_t k = t_[x].is("(") ? closing(x) : x + 1;
        if (k == 0) return x;
        while (k < f.body.end) {
            if (t_[k].is(".") && t_[k + 1].isIdent()) {
                k += 2;
            } else if (t_[k].is("[") || (t_[k].is("(") && t_[k - 1].isIdent())) {
                k = closing(k);
                if (k == 0) return x;
            } else {
                break;
            }
        }
        return k;
    }
    // `g(..., e, ...)`, g the effect's own function with one overload of that many parameters, e
    // given to an `in` parameter of a struct type.
    void passed(const FxFunction& f, size_t i) {
        if (!t_[i].isIdent() || !t_[i + 1].is("(") || t_[i - 1].is(".") || !syntax_.findFunction(t_[i].text)) return;
        std::vector<std::pair<size_t, size_t>> arguments;
        if (!t_[i + 2].is(")"))
            for (size_t k = i + 2;; k = arguments.back().second + 1) {
                arguments.push_back({k, expressionEnd(f, k)});
                if (!t_[arguments.back().second].is(",")) break;
            }
        if (!arguments.empty() && !t_[arguments.back().second].is(")")) return;
        const FxFunction* callee = nullptr;
        for (const FxFunction& g : syntax_.functions) {
            if (g.name != t_[i].text || g.parameters.size() != arguments.size()) continue;
            if (callee) return;  // overloads: glslang's choice
            callee = &g;
        }
        if (!callee) return;
        for (size_t a = 0; a < arguments.size(); ++a) {
            const FxParameter& p = callee->parameters[a];
            const bool writes = std::any_of(p.modifiers.begin(), p.modifiers.end(), [](const std::string& m) { return m == "out" || m == "inout"; });
            if (!writes && p.arrayDims.empty()) convertInPlace(f, arguments[a].first, arguments[a].second, {p.type, {}}, false, arguments[a].first);
        }
    }

    // Whether token i starts a statement: after `;`, a brace, `else` or the condition of an `if`,
    // `for` or `while`.
    bool startsStatement(const FxFunction& f, size_t i) const {
        if (i <= f.body.begin) return false;
        const Token& before = t_[i - 1];
        if (isBoundary(before) || before.is("else")) return true;
        if (!before.is(")")) return false;
        int depth = 0;
        for (size_t k = i - 1; k > f.body.begin; --k) {
            if (t_[k].is(")")) ++depth;
            if (t_[k].is("(") && --depth == 0) return t_[k - 1].is("if") || t_[k - 1].is("for") || t_[k - 1].is("while");
        }
        return false;
    }
    // The token ending the expression that starts at `begin`: the first `;` or `,` outside brackets,
    // or the bracket closing around it.
    size_t expressionEnd(const FxFunction& f, size_t begin) const {
        int depth = 0;
        size_t k = begin;
        for (; k < f.body.end; ++k) {
            if (depth == 0 && (t_[k].is(";") || t_[k].is(","))) break;
            if (t_[k].is("(") || t_[k].is("[") || t_[k].is("{")) ++depth;
            if ((t_[k].is(")") || t_[k].is("]") || t_[k].is("}")) && --depth < 0) break;
        }
        return k;
    }
    // The type of tokens [b, e): a variable named alone as declared, else the expression's type
    // (expression_types.h); nothing where it is not evident or glslang would see another type (a
    // one-component vector, a one-row matrix kept a matrix).
    std::optional<DeclaredVariable> typeOf(const FxFunction& f, size_t b, size_t e) const {
        if (e == b + 1 && t_[b].isIdent()) return declaredVariable(syntax_, f, t_[b].text, b);
        auto type = expressionType(syntax_, f, b, e);
        if (!type || type->keptMatrix || type->vector1) return std::nullopt;
        for (int d : type->dims)
            if (d <= 0) return std::nullopt;
        if (!type->structName.empty()) return DeclaredVariable{type->structName, type->dims};
        if (!type->basic.ok) return std::nullopt;
        return DeclaredVariable{spellType(type->basic), type->dims};
    }
    bool isAggregate(const DeclaredVariable& d) const { return !d.dims.empty() || syntax_.findStruct(syntax_.resolveType(d.type)); }

    // Expression [b, e) (written from token `from`, which a cast's parenthesis precedes) becomes a
    // call of the function converting it to struct `to`, where fxc converts it.
    void convertInPlace(const FxFunction& f, size_t b, size_t e, const DeclaredVariable& to, bool explicitCast, size_t from) {
        if (!to.dims.empty() || !syntax_.findStruct(syntax_.resolveType(to.type))) return;
        const std::string name = define(f, b, e, to, explicitCast);
        if (name.empty()) return;
        edits.push_back({t_[from].offset, t_[b].offset, " " + name + "("});
        edits.push_back({t_[e - 1].end, t_[e - 1].end, ")"});
    }

    // The function converting the value of [b, e) to `to`, defined before the first function that
    // needs it; empty where fxc does not convert: implicitly when both are structs or arrays whose
    // components match one for one in type (componentwise-equal), by a cast when the source has at
    // least as many components (each converted). Objects take only their type. A struct is
    // returned; an array, which no function returns, is written to the first (out) parameter.
    // A cast of a value whose type the rewrite cannot tell (`(Pair)t.Sample(s, uv)`, a method's
    // result) gets overloads for every vector and matrix that can be cast to the struct, and for
    // the struct itself and the scalars: glslang picks the one of the value's type.
    std::string define(const FxFunction& f, size_t b, size_t e, const DeclaredVariable& to, bool explicitCast = false) {
        auto source = typeOf(f, b, e);
        if (!isAggregate(to)) return {};
        if (!source) return explicitCast && to.dims.empty() ? defineForAnySource(f, to) : std::string();
        const std::string target = syntax_.resolveType(to.type);
        const bool aggregate = isAggregate(*source);
        if ((!aggregate && !explicitCast) || (syntax_.resolveType(source->type) == target && source->dims == to.dims)) return {};
        std::string name = "fxport_convert_" + identifierPart(syntax_.resolveType(source->type));
        for (int d : source->dims) name += "_" + std::to_string(d);
        name += "_to_" + identifierPart(target);
        for (int d : to.dims) name += "_" + std::to_string(d);
        const std::string definition = conversion(name, *source, to, explicitCast);
        if (definition.empty()) return {};
        if (defined_.insert(name).second)  // one line: the rewrite keeps the line count
            edits.push_back({t_[f.declaration.begin].offset, t_[f.declaration.begin].offset, definition});
        return name;
    }
    // The overloads of `fxport_cast_to_T` (see define()); empty when T holds an object.
    std::string defineForAnySource(const FxFunction& f, const DeclaredVariable& to) {
        const std::string name = "fxport_cast_to_" + identifierPart(syntax_.resolveType(to.type));
        if (defined_.count(name)) return name;
        std::vector<AggregateComponent> out;
        if (!aggregateComponents(syntax_, to.type, {}, "r", false, out, true)) return {};
        for (const auto& c : out)
            if (c.object) return {};
        std::string definitions = to.type + " " + name + "(" + to.type + " x) { return x; } ";
        for (const char* scalar : {"float", "int", "uint", "bool"}) {
            // A scalar fills every member, as glslang's own cast of one does.
            definitions += to.type + " " + name + "(" + scalar + " x) { " + to.type + " r; ";
            for (const auto& c : out) definitions += c.access + " = (" + c.scalar + ")x; ";
            definitions += "return r; } ";
            for (size_t n = std::max<size_t>(2, out.size()); n <= 4; ++n)
                definitions += conversion(name, {scalar + std::to_string(n), {}}, to, true);
            for (int rows = 2; rows <= 4; ++rows)
                for (int columns = 2; columns <= 4; ++columns)
                    if (size_t(rows * columns) == out.size())
                        definitions += conversion(name, {scalar + std::to_string(rows) + "x" + std::to_string(columns), {}}, to, true);
        }
        defined_.insert(name);
        edits.push_back({t_[f.declaration.begin].offset, t_[f.declaration.begin].offset, definitions});
        return name;
    }
    // The definition of function `name` converting a `source` to `to` (one line); empty where fxc
    // does not convert.
    std::string conversion(const std::string& name, const DeclaredVariable& source, const DeclaredVariable& to, bool explicitCast) const {
        const bool aggregate = isAggregate(source);
        std::vector<AggregateComponent> in, out;
        if (!aggregateComponents(syntax_, source.type, source.dims, "x", false, in, true) ||
            !aggregateComponents(syntax_, to.type, to.dims, "r", false, out, true) || (explicitCast ? in.size() < out.size() : in.size() != out.size()))
            return {};
        if (!aggregate && !matrixCastFits(source, in.size(), out.size())) return {};
        std::string body;
        for (size_t k = 0; k < out.size(); ++k) {
            if (in[k].object != out[k].object || ((in[k].object || !explicitCast) && in[k].scalar != out[k].scalar)) return {};
            if (out[k].object && !to.dims.empty()) return {};  // an array of objects as an out parameter: left to glslang
            body += out[k].access + " = " + (out[k].object ? "" : "(" + out[k].scalar + ")") + in[k].access + "; ";
        }
        const std::string parameter = source.type + " x" + dimsSpelled(source.dims);
        return to.dims.empty() ? to.type + " " + name + "(" + parameter + ") { " + to.type + " r; " + body + "return r; } "
                               : "void " + name + "(out " + to.type + " r" + dimsSpelled(to.dims) + ", " + parameter + ") { " + body + "} ";
    }
    // A matrix of more than one row and column cast to a struct takes exactly its count (fxc X3017).
    bool matrixCastFits(const DeclaredVariable& source, size_t have, size_t want) const {
        BasicType b = describeBasicType(syntax_.resolveType(source.type));
        return !(b.ok && b.isMatrix && b.rows > 1 && b.columns > 1 && have != want);
    }

    const EffectSyntax& syntax_;
    const std::vector<Token>& t_;
    std::set<std::string> defined_;
};

}  // namespace

std::vector<TextEdit> aggregateConversions(const EffectSyntax& syntax) {
    Conversions conversions(syntax);
    for (const FxFunction& f : syntax.functions)
        if (!f.body.empty()) conversions.in(f);
    return std::move(conversions.edits);
}

}  // namespace fxport::xlate
