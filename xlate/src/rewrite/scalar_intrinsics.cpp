// See scalar_intrinsics.h.
#include "rewrite/scalar_intrinsics.h"

#include <algorithm>
#include <set>
#include <string>
#include <string_view>

#include "hlsl/call_arguments.h"
#include "hlsl/hlsl_types.h"
#include "hlsl/variable_declarations.h"

namespace fxport::xlate {

namespace {

struct Helper {
    const char* name;
    size_t arguments;
    bool matrixOnly;   // takes a scalar or a matrix, not a float1 (fxc refuses determinant(float1))
    const char* code;  // the helper's definition
};

const Helper kHelpers[] = {
    {"normalize", 1, false, "float fxport_normalize_scalar(float x) { return x * rsqrt(x * x); } "},
    {"determinant", 1, true, "float fxport_determinant_scalar(float x) { return x; } "},
    {"transpose", 1, true, "float fxport_transpose_scalar(float x) { return x; } "},
    {"noise", 1, false, "float fxport_noise_scalar(float x) { return noise(float2(x, 0.0)); } "},
    {"reflect", 2, false, "float fxport_reflect_scalar(float i, float n) { return i - 2.0 * n * (i * n); } "},
    {"refract", 3, false,
     "float fxport_refract_scalar(float i, float n, float eta) { float c = i * n; float k = 1.0 - eta * eta * (1.0 - c * c); "
     "return k < 0.0 ? 0.0 : eta * i - (eta * c + sqrt(k)) * n; } "},
};

// Whether tokens [b, e) of `f` are evidently one scalar: a number, or a variable declared as one.
bool isScalar(const EffectSyntax& syntax, const FxFunction& f, size_t b, size_t e, bool matrixOnly) {
    const auto& t = syntax.tokens;
    if (e == b + 2 && t[b].is("-")) ++b;
    if (e != b + 1) return false;
    if (t[b].kind == Token::Kind::Number) return true;
    if (!t[b].isIdent()) return false;
    auto d = declaredVariable(syntax, f, t[b].text, b);
    if (!d || !d->dims.empty()) return false;
    BasicType type = describeBasicType(syntax.resolveType(d->type));
    return type.ok && type.rows * type.columns == 1 && (!matrixOnly || type.isMatrix || type.scalar == syntax.resolveType(d->type));
}

// Whether tokens [b, e) of `f` are one local variable or parameter declared as a matrix of one row
// or one column (float1x1, float2x1, float1x3 ...): fxc's determinant of a non-square matrix is that of its
// top-left square, here its first element (degenerate_matrices.h makes such a matrix a vector,
// whose .x it is; glslang takes no float1 where the helper's float is).
bool isOneLineMatrix(const EffectSyntax& syntax, const FxFunction& f, size_t b, size_t e) {
    const auto& t = syntax.tokens;
    if (e != b + 1 || !t[b].isIdent()) return false;
    // A local, a parameter or a uniform read as a vector (degenerate_matrices.h); a struct member
    // or an array element keeps its matrix type.
    const bool parameter = std::any_of(f.parameters.begin(), f.parameters.end(), [&](const FxParameter& p) { return p.name == t[b].text; });
    const bool uniform = std::any_of(syntax.globals.begin(), syntax.globals.end(),
                                     [&](const FxGlobal& g) { return g.name == t[b].text && isVectorUniform(syntax, g); });
    if (!parameter && !uniform && !f.declarationSites.count(t[b].text)) return false;
    auto d = declaredVariable(syntax, f, t[b].text, b);
    if (!d || !d->dims.empty()) return false;
    BasicType type = describeBasicType(syntax.resolveType(d->type));
    return type.ok && type.isMatrix && (type.rows == 1 || type.columns == 1);
}

}  // namespace

std::vector<TextEdit> scalarIntrinsicCalls(const EffectSyntax& syntax) {
    std::vector<TextEdit> edits;
    if (syntax.functions.empty()) return edits;
    const auto& t = syntax.tokens;
    std::set<const Helper*> used;
    for (const auto& f : syntax.functions) {
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
            if (!t[i].isIdent() || !t[i + 1].is("(") || (i > 0 && t[i - 1].is("."))) continue;
            for (const Helper& h : kHelpers) {
                if (t[i].text != h.name || syntax.findFunction(h.name)) continue;
                auto args = callArgumentSpans(t, i + 1, f.body.end);
                if (args.size() != h.arguments) continue;
                if (std::string_view(h.name) == "determinant" && isOneLineMatrix(syntax, f, args[0].first, args[0].second)) {
                    edits.push_back({t[i].offset, t[i].end, std::string("fxport_") + h.name + "_scalar"});
                    edits.push_back({t[args[0].first].end, t[args[0].first].end, ".x"});
                    used.insert(&h);
                    continue;
                }
                bool scalars = true;
                for (const auto& [b, e] : args) scalars = scalars && isScalar(syntax, f, b, e, h.matrixOnly);
                if (!scalars) continue;
                edits.push_back({t[i].offset, t[i].end, std::string("fxport_") + h.name + "_scalar"});
                used.insert(&h);
            }
        }
    }
    if (used.empty()) return edits;
    size_t first = syntax.functions.front().declaration.begin;
    for (const auto& f : syntax.functions) first = std::min(first, f.declaration.begin);
    std::string helpers;
    for (const Helper& h : kHelpers)
        if (used.count(&h)) helpers += h.code;
    edits.push_back({t[first].offset, t[first].offset, helpers});
    return edits;
}

}  // namespace fxport::xlate
