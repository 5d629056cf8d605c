// fxc indexes with a scalar only (vkd3d's vector-indexing): `vec[idx]` with `int1 idx` or
// `int2 idx` is refused, though a one-component vector converts to a scalar elsewhere; glslang
// takes the first component. Judged where the index is a plain name whose declaration is evident.
#include "checks/fxc_checks.h"
#include "hlsl/aggregate_components.h"
#include "hlsl/hlsl_types.h"
#include "hlsl/variable_declarations.h"

namespace fxport::xlate {

namespace {

class IndexTypes : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    // The `[` at `open` subscripts a texture or its `.mips[m]` / `.sample[s]` (an int2 or int3
    // texel address there): the name before any earlier subscripts is a resource or such a member.
    bool indexesResource(const FxFunction& f, size_t open) const {
        size_t k = open;
        while (k > f.body.begin && t_[k - 1].is("]")) {
            int depth = 0;
            for (--k; k > f.body.begin; --k) {
                if (t_[k].is("]")) ++depth;
                if (t_[k].is("[") && --depth == 0) break;
            }
        }
        if (k <= f.body.begin || !t_[k - 1].isIdent()) return false;
        const Token& base = t_[k - 1];
        if ((base.is("mips") || base.is("sample")) && t_[k - 2].is(".")) return true;
        if (t_[k - 2].is("."))  // `out.m_image[p]`: a struct's texture member (MAGE's OutputTexturesMSAA)
            for (const auto& s : syntax_.structs)
                for (const auto& m : s.members)
                    if (m.name == base.text && isResourceType(syntax_.resolveType(m.type))) return true;
        for (const auto& t : syntax_.textures)
            if (t.name == base.text) return true;
        auto v = declaredVariable(syntax_, f, base.text, k - 1);
        return v && isResourceType(syntax_.resolveType(v->type));
    }

    void run() {
        for (const auto& f : syntax_.functions)
            for (size_t i = f.body.begin + 1; i + 2 < f.body.end; ++i) {
                if (!t_[i].is("[") || !t_[i + 1].isIdent() || !t_[i + 2].is("]") || !(t_[i - 1].isIdent() || t_[i - 1].is("]"))) continue;
                if (indexesResource(f, i)) continue;
                auto v = declaredVariable(syntax_, f, t_[i + 1].text, i + 1);
                if (!v || !v->dims.empty()) continue;
                const std::string& type = syntax_.resolveType(v->type);
                BasicType b = describeBasicType(type);
                bool oneComponentVector = !type.empty() && (type.back() == '1' || type.rfind("vector", 0) == 0);  // int1, vector<int, 1>
                if (b.ok && (b.isMatrix || b.columns > 1 || oneComponentVector))
                    report("array index '" + t_[i + 1].text + "' is of type " + v->type + ": fxc indexes with a scalar only", i + 1);
            }
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findIndexTypeErrors(const EffectSyntax& syntax, const SourceMap& map) {
    IndexTypes check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
