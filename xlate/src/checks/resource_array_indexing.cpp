// Before SM 5.1 an array of textures or UAVs is a set of separate registers: fxc needs each index
// known at compile time (a literal, or a loop counter it unrolls), and refuses an index that only
// the application knows (vkd3d's object-references: `tex[n].Load(0)` with `uniform int n`). GLSL
// 4.5 indexes sampler arrays dynamically, so glslang takes it. Judged where the index is plainly a
// uniform (a non-static global): what depends on loop counters is left alone.
#include <algorithm>
#include <set>

#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

bool isObjectType(const std::string& t) {
    for (const char* prefix : {"Texture", "RWTexture", "Buffer", "RWBuffer", "StructuredBuffer", "RWStructuredBuffer", "ByteAddressBuffer",
                               "RWByteAddressBuffer"})
        if (t.rfind(prefix, 0) == 0) return true;
    return false;
}

class ResourceArrayIndexing : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        std::set<std::string> arrays = resourceArrays();
        if (arrays.empty()) return;
        for (const auto& f : syntax_.functions)
            for (size_t i = f.body.begin; i + 3 < f.body.end; ++i)
                if (t_[i].isIdent() && arrays.count(t_[i].text) && t_[i + 1].is("[") && t_[i + 2].isIdent() && t_[i + 3].is("]") &&
                    !(i > 0 && t_[i - 1].is(".")) && isUniform(t_[i + 2].text) && !declaredIn(f, t_[i + 2].text, i))
                    report("resource array '" + t_[i].text + "' is indexed by uniform '" + t_[i + 2].text +
                               "': before SM 5.1 a texture or UAV array takes indices known at compile time only",
                           i + 2);
    }

private:
    // File-scope `Texture2D name[N]` / `RWTexture2D<float4> name[N]`.
    std::set<std::string> resourceArrays() const {
        std::set<std::string> out;
        for (size_t i = 0; i + 2 < t_.size(); ++i) {
            if (inFunction(i) || !t_[i + 1].isIdent() || !t_[i + 2].is("[")) continue;
            size_t type = i;
            if (t_[i].is(">")) {  // back to the template's name
                int depth = 0;
                for (size_t j = i + 1; j-- > 0;) {
                    depth += t_[j].is(">") ? 1 : t_[j].is("<") ? -1 : 0;
                    if (depth == 0) {
                        type = j > 0 ? j - 1 : j;
                        break;
                    }
                }
            }
            if (t_[type].isIdent() && isObjectType(t_[type].text)) out.insert(t_[i + 1].text);
        }
        return out;
    }

    bool isUniform(const std::string& name) const {
        for (const auto& g : syntax_.globals)
            if (g.name == name) return std::find(g.modifiers.begin(), g.modifiers.end(), "static") == g.modifiers.end();
        return false;
    }

    // A local or parameter of that name hides the global.
    bool declaredIn(const FxFunction& f, const std::string& name, size_t before) const {
        for (const auto& p : f.parameters)
            if (p.name == name) return true;
        for (size_t j = f.body.begin + 1; j < before; ++j)
            if (t_[j].is(name) && (t_[j - 1].isIdent() || t_[j - 1].is(","))) return true;
        return false;
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findResourceArrayIndexingErrors(const EffectSyntax& syntax, const SourceMap& map) {
    ResourceArrayIndexing check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
