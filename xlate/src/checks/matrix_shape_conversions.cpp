// Conversions of one-row and one-column matrices that fxc refuses. fxport gives glslang those
// matrices as vectors (degenerate_matrices.h), which would let through what fxc stops (vkd3d's
// return-implicit-conversion, cast-componentwise-compatible and distance pin these):
//  - a matrix to a matrix with fewer rows or columns only (float3x1 from float1x3 fails, X3017);
//  - a vector to a matrix of another component count, implicitly or by a cast (float3x1 from
//    float4, X3017); a matrix to a vector of more components, or a full matrix to a vector;
//  - a matrix passed to an intrinsic that takes vectors only (dot, normalize, dst ..., X3013).
// Only where the types are evident from the source (a constructor, a cast, a variable) and a
// one-row or one-column matrix takes part; the rest glslang judges as before.
#include <algorithm>
#include <optional>
#include <set>

#include "checks/fxc_checks.h"
#include "hlsl/hlsl_types.h"
#include "hlsl/variable_declarations.h"

namespace fxport::xlate {

namespace {

bool isDegenerate(const BasicType& b) { return b.isMatrix && (b.rows == 1 || b.columns == 1); }

std::string spell(const BasicType& b) {
    if (b.isMatrix) return b.scalar + std::to_string(b.rows) + "x" + std::to_string(b.columns);
    return b.columns > 1 ? b.scalar + std::to_string(b.columns) : b.scalar;
}

// Whether fxc converts `from` to `to` (componentwise numeric types).
bool converts(const BasicType& from, const BasicType& to) {
    const int fromCount = from.rows * from.columns, toCount = to.rows * to.columns;
    if (fromCount == 1) return true;
    if (from.isMatrix && to.isMatrix) return from.rows >= to.rows && from.columns >= to.columns;
    if (to.isMatrix) return fromCount == toCount || (to.rows == 1 && fromCount >= toCount);  // a vector is a row
    if (from.isMatrix) return fromCount == toCount || (isDegenerate(from) && fromCount >= toCount);
    return true;
}

class MatrixShapeConversions : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& f : syntax_.functions) {
            if (f.body.empty()) continue;
            for (size_t i = f.body.begin; i < f.body.end; ++i) checkAt(f, i);
        }
    }

private:
    std::optional<BasicType> numeric(const std::string& type) const {
        BasicType b = describeBasicType(syntax_.resolveType(type));
        if (!b.ok) return std::nullopt;
        return b;
    }

    std::optional<BasicType> variableType(const FxFunction& f, const std::string& name, size_t at) const {
        auto d = declaredVariable(syntax_, f, name, at);
        if (!d || !d->dims.empty()) return std::nullopt;
        return numeric(d->type);
    }

    // The type of tokens [b, e) when evident: `T(...)`, `(T) x`, or a variable.
    std::optional<BasicType> typeOf(const FxFunction& f, size_t b, size_t e) const {
        if (e <= b) return std::nullopt;
        if (e == b + 1 && t_[b].isIdent()) return variableType(f, t_[b].text, b);
        if (t_[b].isIdent() && t_[b + 1].is("(") && closing(b + 1) == e - 1) return numeric(t_[b].text);
        if (t_[b].is("(") && b + 2 < e && t_[b + 1].isIdent() && t_[b + 2].is(")")) return numeric(t_[b + 1].text);
        return std::nullopt;
    }

    // One past the expression starting at i: up to `;`, `,` or an unmatched closing bracket.
    size_t expressionEnd(size_t i, size_t end) const {
        for (; i < end; ++i) {
            if (t_[i].is("(") || t_[i].is("[") || t_[i].is("{")) i = closing(i);
            else if (t_[i].is(";") || t_[i].is(",") || t_[i].is(")") || t_[i].is("]") || t_[i].is("}")) return i;
        }
        return end;
    }

    void check(const std::optional<BasicType>& from, const std::optional<BasicType>& to, size_t at, bool cast) {
        if (!from || !to || converts(*from, *to)) return;
        // What glslang judges as fxc does: conversions without a one-row or one-column matrix,
        // except casts between a matrix and a vector (glslang takes `(float3) float2x2`).
        const bool matrixCast = cast && (from->isMatrix || to->isMatrix);
        if (!isDegenerate(*from) && !isDegenerate(*to) && !matrixCast) return;
        report(std::string("cannot ") + (cast ? "" : "implicitly ") + "convert from '" + spell(*from) + "' to '" + spell(*to) + "' (fxc X3017)", at);
    }

    void checkAt(const FxFunction& f, size_t i) {
        const Token& tk = t_[i];
        if (tk.is("return")) {
            size_t e = expressionEnd(i + 1, f.body.end);
            check(typeOf(f, i + 1, e), numeric(f.returnType), i, false);
        } else if (tk.is("=") && i >= 2 && t_[i - 1].isIdent()) {
            size_t e = expressionEnd(i + 1, f.body.end);
            // `T name = x` declares; `name = x` at a statement's start assigns.
            std::optional<BasicType> to;
            if (t_[i - 2].isIdent() && numeric(t_[i - 2].text)) to = numeric(t_[i - 2].text);
            else if (t_[i - 2].is(";") || t_[i - 2].is("{") || t_[i - 2].is("}")) to = variableType(f, t_[i - 1].text, i - 1);
            check(typeOf(f, i + 1, e), to, i, false);
        } else if (tk.is("(") && i + 3 < f.body.end && t_[i + 1].isIdent() && t_[i + 2].is(")") &&
                   (!t_[i - 1].isIdent() || t_[i - 1].is("return")) &&
                   numeric(t_[i + 1].text)) {
            size_t e = i + 3;  // `(T) x` or `(T) U(...)`
            if (t_[e].isIdent() && t_[e + 1].is("(")) e = closing(e + 1) + 1;
            else if (t_[e].isIdent()) e += 1;
            else return;
            if (e < f.body.end && (t_[e].is(".") || t_[e].is("["))) return;  // the cast applies to a member or element
            check(typeOf(f, i + 3, e), numeric(t_[i + 1].text), i, true);
        } else if (tk.isIdent() && vectorOnly(tk.text) && t_[i + 1].is("(") && !t_[i - 1].is(".")) {
            size_t close = closing(i + 1);
            for (size_t a = i + 2; a < close;) {
                size_t e = expressionEnd(a, close);
                if (auto b = typeOf(f, a, e); b && isDegenerate(*b))
                    report("'" + tk.text + "' takes vectors; argument '" + spell(*b) + "' is a matrix (fxc X3013)", a);
                a = e + 1;
            }
        }
    }

    static bool vectorOnly(const std::string& s) {
        static const std::set<std::string> k = {"dot", "normalize", "length", "distance", "dst", "cross", "reflect", "refract", "faceforward"};
        return k.count(s) > 0;
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findMatrixShapeConversionErrors(const EffectSyntax& syntax, const SourceMap& map) {
    MatrixShapeConversions check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
