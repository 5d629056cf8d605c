// fxc's rules for a function's signature that glslang does not check (vkd3d's function and
// invalid pin them):
//  - an out or inout parameter has no default value (there is nothing for the default to fill);
//  - a function's result is not `uniform` (a modifier of variables and parameters).
#include <algorithm>

#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

class FunctionSignatures : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& f : syntax_.functions) {
            for (const auto& p : f.parameters) {
                bool out = std::find(p.modifiers.begin(), p.modifiers.end(), "out") != p.modifiers.end() ||
                           std::find(p.modifiers.begin(), p.modifiers.end(), "inout") != p.modifiers.end();
                if (out && !p.defaultValue.empty())
                    report("output parameter '" + p.name + "' of '" + f.name + "' cannot have a default value", p.defaultValue.begin);
            }
            for (size_t i = f.declaration.begin; i < f.token && i < t_.size(); ++i)
                if (t_[i].is("uniform")) report("function '" + f.name + "' cannot return a uniform: 'uniform' is for variables and parameters", i);
        }
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findFunctionSignatureErrors(const EffectSyntax& syntax, const SourceMap& map) {
    FunctionSignatures check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
