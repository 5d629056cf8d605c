// fxc addresses a vector's components by a variable index only when reading (vkd3d's
// vector-indexing-uniform: `color[i]` with a uniform `i` compiles); a write through such an index,
// `p[i] = 2.0;` with `p` a float4 and `i` a uniform, is refused ("array reference cannot be used
// as an l-value; not natively addressable", vkd3d's vector-indexing). glslang writes the component.
// Judged where fxc certainly cannot fold the index: a plain name of a uniform (a $Globals or
// cbuffer variable, not static, not const) not shadowed in the function, indexing a vector
// variable (not an array) that is then assigned; a loop counter or a constant is fxc's to unroll
// or fold and is left alone.
#include <algorithm>

#include "checks/fxc_checks.h"
#include "hlsl/hlsl_types.h"
#include "hlsl/variable_declarations.h"

namespace fxport::xlate {

namespace {

bool has(const std::vector<std::string>& modifiers, const char* m) {
    return std::find(modifiers.begin(), modifiers.end(), m) != modifiers.end();
}

bool isWrite(const Token& t) {
    for (const char* op : {"=", "+=", "-=", "*=", "/=", "%=", "&=", "|=", "^=", "<<=", ">>=", "++", "--"})
        if (t.is(op)) return true;
    return false;
}

class VectorElementWrites : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& f : syntax_.functions)
            for (size_t i = f.body.begin + 1; i + 3 < f.body.end; ++i) {
                if (!t_[i].isIdent() || !t_[i + 1].is("[") || !t_[i + 2].isIdent() || !t_[i + 3].is("]") || !isWrite(tok(i + 4))) continue;
                if (i > 0 && t_[i - 1].is(".")) continue;  // a member: its type is not looked up here
                if (!isVector(f, t_[i].text, i) || !isUniform(f, t_[i + 2].text, i + 2)) continue;
                report("vector '" + t_[i].text + "' is written at index '" + t_[i + 2].text +
                           "', a uniform: fxc writes a vector's component only at a constant index (not natively addressable)",
                       i + 2);
            }
    }

private:
    bool isVector(const FxFunction& f, const std::string& name, size_t at) const {
        auto v = declaredVariable(syntax_, f, name, at);
        if (!v || !v->dims.empty()) return false;
        BasicType b = describeBasicType(syntax_.resolveType(v->type));
        return b.ok && !b.isMatrix && b.columns > 1;
    }

    // A global the application sets, seen from `at` in `f` (no parameter or earlier local of the name).
    bool isUniform(const FxFunction& f, const std::string& name, size_t at) const {
        for (const auto& p : f.parameters)
            if (p.name == name) return false;
        auto sites = f.declarationSites.find(name);
        if (sites != f.declarationSites.end())
            for (size_t s : sites->second)
                if (s < at) return false;
        for (const auto& g : syntax_.globals)
            if (g.name == name) return g.arrayDims.empty() && !has(g.modifiers, "static") && !has(g.modifiers, "const");
        return false;
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findVectorElementWriteErrors(const EffectSyntax& syntax, const SourceMap& map) {
    VectorElementWrites check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
