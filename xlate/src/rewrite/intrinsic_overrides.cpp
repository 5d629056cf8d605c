// See intrinsic_overrides.h.
#include "rewrite/intrinsic_overrides.h"

#include <set>
#include <string>

#include "hlsl/expression_types.h"

namespace fxport::xlate {

namespace {

const std::set<std::string> kIntrinsics = {
    "abs",   "acos",  "all",         "any",    "asin",   "atan",     "atan2",   "ceil",     "clamp",     "cos",   "cosh",
    "cross", "ddx",   "ddy",         "degrees", "determinant", "distance", "dot", "exp", "exp2", "faceforward", "floor",
    "fmod",  "frac",  "fwidth",      "ldexp",  "length", "lerp",     "lit",     "log",      "log10",     "log2",  "mad",
    "max",   "min",   "mul",         "noise",  "normalize", "pow",   "radians", "rcp",      "reflect",   "refract", "round",
    "rsqrt", "saturate", "sign",     "sin",    "sinh",   "smoothstep", "sqrt",  "step",     "tan",       "tanh",  "transpose",
    "trunc"};

// Whether fxc converts a value of type `arg` to parameter type `param` implicitly.
bool converts(const ExpressionType& arg, const std::string& paramType, const std::vector<int>& paramDims, const EffectSyntax& syntax) {
    const std::string& resolved = syntax.resolveType(paramType);
    if (!arg.dims.empty() || !paramDims.empty()) return arg.dims == paramDims && (arg.structName.empty() ? arg.basic.ok : arg.structName == resolved);
    if (!arg.structName.empty()) return arg.structName == resolved;
    const BasicType p = describeBasicType(resolved), a = arg.basic;
    if (!p.ok || !a.ok) return false;
    const int pn = p.rows * p.columns, an = a.rows * a.columns;
    if (an == 1 || pn == 1) return true;                                                   // a scalar fills; truncation to one
    if (a.isMatrix && p.isMatrix) return a.rows >= p.rows && a.columns >= p.columns;
    if (!a.isMatrix && !p.isMatrix) return a.columns >= p.columns;                           // vectors truncate
    return an == pn;
}

}  // namespace

std::vector<TextEdit> intrinsicOverrides(const EffectSyntax& syntax) {
    std::vector<TextEdit> edits;
    std::set<std::string> overridden;
    const auto& t = syntax.tokens;
    std::set<std::string> compiled;  // entry points keep their names (`compile ps_2_0 name()`)
    for (size_t i = 0; i + 2 < t.size(); ++i)
        if (t[i].is("compile")) compiled.insert(t[i + 2].text);
    for (const auto& f : syntax.functions)
        if (kIntrinsics.count(f.name) && !compiled.count(f.name)) {
            overridden.insert(f.name);
            edits.push_back({t[f.token].offset, t[f.token].end, "fxport_user_" + f.name});
        }
    if (overridden.empty()) return edits;
    for (const auto& f : syntax.functions) {
        for (size_t i = f.body.begin; i + 1 < f.body.end; ++i) {
            if (!t[i].isIdent() || !overridden.count(t[i].text) || !t[i + 1].is("(") || (i > 0 && t[i - 1].is("."))) continue;
            // The arguments: spans at depth 1.
            std::vector<std::pair<size_t, size_t>> spans;
            int depth = 0;
            size_t start = i + 2, j = i + 1;
            for (; j < f.body.end; ++j) {
                if (t[j].is("(") || t[j].is("[") || t[j].is("{")) ++depth;
                else if ((t[j].is(")") || t[j].is("]") || t[j].is("}")) && --depth == 0) break;
                else if (depth == 1 && t[j].is(",")) spans.push_back({start, j}), start = j + 1;
            }
            if (j > start) spans.push_back({start, j});
            bool chosen = false;
            for (const auto& user : syntax.functions) {
                if (user.name != t[i].text || user.parameters.size() != spans.size()) continue;
                bool all = true;
                for (size_t a = 0; a < spans.size() && all; ++a) {
                    auto type = expressionType(syntax, f, spans[a].first, spans[a].second);
                    all = !type || converts(*type, user.parameters[a].type, user.parameters[a].arrayDims, syntax);
                }
                chosen = chosen || all;
            }
            if (chosen) edits.push_back({t[i].offset, t[i].end, "fxport_user_" + t[i].text});
        }
    }
    return edits;
}

}  // namespace fxport::xlate
