// See aggregate_conversions.h.
#include "rewrite/aggregate_conversions.h"

#include <algorithm>
#include <cctype>
#include <set>
#include <string>

#include "hlsl/aggregate_components.h"
#include "hlsl/hlsl_types.h"
#include "hlsl/variable_declarations.h"

namespace fxport::xlate {

namespace {

std::string identifierPart(const std::string& text) {
    std::string out;
    for (char c : text) out += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
    return out;
}

bool isBoundary(const Token& t) { return t.is(";") || t.is("{") || t.is("}"); }

class Conversions {
public:
    explicit Conversions(const EffectSyntax& syntax) : syntax_(syntax), t_(syntax.tokens) {}

    void in(const FxFunction& f) {
        for (size_t i = f.body.begin; i + 2 < f.body.end; ++i) {
            returned(f, i);
            initialized(f, i);
            cast(f, i);
            passed(f, i);
        }
    }
    std::vector<TextEdit> edits;

private:
    // `return x;`: to the function's return type.
    void returned(const FxFunction& f, size_t i) {
        if (t_[i].is("return") && t_[i + 1].isIdent() && t_[i + 2].is(";")) convert(f, i + 1, {f.returnType, {}}, false, i + 1);
    }
    // `[const] T y = x;`, T a struct (a local static's initializer is no place for a call).
    void initialized(const FxFunction& f, size_t i) {
        if (i + 4 >= f.body.end || !t_[i].isIdent() || !t_[i + 1].isIdent() || !t_[i + 2].is("=") || !t_[i + 3].isIdent() || !t_[i + 4].is(";"))
            return;
        for (size_t k = i; k > f.body.begin && !isBoundary(t_[k - 1]); --k)
            if (t_[k - 1].is("static")) return;
        convert(f, i + 3, {t_[i].text, {}}, false, i + 3);
    }
    // `(T) x` of a struct T in an expression; `y = (T) x;` alone is componentwise_casts.h's.
    void cast(const FxFunction& f, size_t i) {
        size_t j = i + 1;
        if (!t_[i].is("(") || (t_[i - 1].isIdent() && !t_[i - 1].is("return"))) return;
        if (t_[j].is("struct")) ++j;
        if (j + 2 >= f.body.end || !t_[j].isIdent() || !t_[j + 1].is(")") || !t_[j + 2].isIdent()) return;
        const size_t x = j + 2;
        if (t_[x + 1].is(".") || t_[x + 1].is("[") || t_[x + 1].is("(")) return;
        if (t_[i - 1].is("=") && t_[i - 2].isIdent() && isBoundary(t_[i - 3]) && t_[x + 1].is(";")) return;
        convert(f, x, {t_[j].text, {}}, true, i);
    }
    // `g(..., x, ...)`, g the effect's own function with one overload of that many parameters, x
    // given to an `in` parameter of a struct type.
    void passed(const FxFunction& f, size_t i) {
        if (!t_[i].isIdent() || !t_[i + 1].is("(") || t_[i - 1].is(".") || !syntax_.findFunction(t_[i].text)) return;
        std::vector<size_t> lone;  // per argument: its token when it is one identifier, else 0
        int depth = 0;
        for (size_t k = i + 1; k < f.body.end; ++k) {
            if (t_[k].is("(") || t_[k].is("[") || t_[k].is("{")) ++depth;
            if (t_[k].is(")") || t_[k].is("]") || t_[k].is("}")) --depth;
            if (depth == 0) break;
            if (depth == 1 && (t_[k].is("(") || t_[k].is(",")) && !t_[k + 1].is(")"))
                lone.push_back(t_[k + 1].isIdent() && (t_[k + 2].is(",") || t_[k + 2].is(")")) ? k + 1 : 0);
        }
        const FxFunction* callee = nullptr;
        for (const FxFunction& g : syntax_.functions) {
            if (g.name != t_[i].text || g.parameters.size() != lone.size()) continue;
            if (callee) return;  // overloads: glslang's choice
            callee = &g;
        }
        if (!callee) return;
        for (size_t a = 0; a < lone.size(); ++a) {
            const FxParameter& p = callee->parameters[a];
            const bool writes = std::any_of(p.modifiers.begin(), p.modifiers.end(), [](const std::string& m) { return m == "out" || m == "inout"; });
            if (lone[a] && !writes) convert(f, lone[a], {p.type, p.arrayDims}, false, lone[a]);
        }
    }

    // Variable token `x` (written from token `from`) becomes a call of the function converting it to
    // `to`, where fxc converts it: implicitly when each component has the same type and there are as
    // many; by a cast when there are at least as many (each converted). Objects take only their type.
    void convert(const FxFunction& f, size_t x, const DeclaredVariable& to, bool explicitCast, size_t from) {
        auto source = declaredVariable(syntax_, f, t_[x].text, x);
        const std::string target = syntax_.resolveType(to.type);
        if (!source || !to.dims.empty() || !syntax_.findStruct(target)) return;
        const bool aggregate = !source->dims.empty() || syntax_.findStruct(syntax_.resolveType(source->type));
        if ((!aggregate && !explicitCast) || (syntax_.resolveType(source->type) == target && source->dims.empty())) return;
        std::vector<AggregateComponent> in, out;
        if (!aggregateComponents(syntax_, source->type, source->dims, "x", false, in, true) ||
            !aggregateComponents(syntax_, to.type, {}, "r", false, out, true) || (explicitCast ? in.size() < out.size() : in.size() != out.size()))
            return;
        if (!aggregate && !matrixCastFits(*source, in.size(), out.size())) return;
        std::string body;
        for (size_t k = 0; k < out.size(); ++k) {
            if (in[k].object != out[k].object || ((in[k].object || !explicitCast) && in[k].scalar != out[k].scalar)) return;
            body += out[k].access + " = " + (out[k].object ? "" : "(" + out[k].scalar + ")") + in[k].access + "; ";
        }
        std::string dims, name = "fxport_convert_" + identifierPart(syntax_.resolveType(source->type));
        for (int d : source->dims) {
            dims += "[" + std::to_string(d) + "]";
            name += "_" + std::to_string(d);
        }
        name += "_to_" + identifierPart(target);
        if (defined_.insert(name).second)  // one line: the rewrite keeps the line count
            edits.push_back({t_[f.declaration.begin].offset, t_[f.declaration.begin].offset,
                             to.type + " " + name + "(" + source->type + " x" + dims + ") { " + to.type + " r; " + body + "return r; } "});
        edits.push_back({t_[from].offset, t_[x].end, " " + name + "(" + t_[x].text + ")"});
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
