// A file-scope `static` struct that holds both an object (a texture, a sampler) and numbers, with
// no initializer, is refused by fxc (vkd3d's invalid: `static struct apple a;` of a sampler and a
// float4); glslang splits the struct silently. With an initializer fxc takes it
// (ReShade's `static const` struct of a sampler and its pixel size compiles with d3dcompiler), so
// only the declaration without one is judged; a struct of objects alone, or of numbers alone,
// is another matter (static-initializer: `static Texture2D tex;` unread compiles).
#include <algorithm>

#include "checks/fxc_checks.h"
#include "hlsl/aggregate_components.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

struct Parts {
    bool object = false, number = false;
};

void partsOf(const EffectSyntax& syntax, const std::string& typeName, Parts& parts, int depth = 0) {
    const std::string& type = syntax.resolveType(typeName);
    if (isResourceType(type)) parts.object = true;
    else if (describeBasicType(type).ok) parts.number = true;
    else if (const FxStruct* s = depth < 8 ? syntax.findStruct(type) : nullptr)
        for (const auto& m : s->members) partsOf(syntax, m.type, parts, depth + 1);
}

class StaticMixedStructs : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& g : syntax_.globals) {
            if (std::find(g.modifiers.begin(), g.modifiers.end(), "static") == g.modifiers.end() || !g.initializer.empty()) continue;
            if (!syntax_.findStruct(syntax_.resolveType(g.type))) continue;
            Parts parts;
            partsOf(syntax_, g.type, parts);
            if (parts.object && parts.number)
                report("static '" + g.name + "' of struct " + g.type +
                           " holds both an object and numbers and has no initial value, which fxc refuses",
                       g.token);
        }
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findStaticMixedStructErrors(const EffectSyntax& syntax, const SourceMap& map) {
    StaticMixedStructs check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
