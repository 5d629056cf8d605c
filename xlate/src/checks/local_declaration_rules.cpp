// fxc's rule for a variable declared in a function body that glslang does not check (vkd3d's
// invalid file): a local is never `uniform` (a uniform is a global or an entry parameter), and
// takes no annotations.
#include "checks/fxc_checks.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

class LocalDeclarationRules : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& f : syntax_.functions)
            for (size_t i = f.body.begin; i + 2 < f.body.end; ++i) {
                bool statementStart = i == f.body.begin || t_[i - 1].is(";") || t_[i - 1].is("{") || t_[i - 1].is("}");
                if (statementStart && t_[i].is("uniform") && t_[i + 1].isIdent())
                    report("local variable in '" + f.name + "' declared uniform: uniforms are globals or entry parameters", i);
                // `float var < int a = 1; > = 0;`: annotations belong to globals (effect-annotations-fx_2).
                if (i + 5 < f.body.end && t_[i].isIdent() && t_[i + 1].isIdent() && t_[i + 2].is("<") && t_[i + 3].isIdent() &&
                    t_[i + 4].isIdent() && t_[i + 5].is("=") && describeBasicType(syntax_.resolveType(t_[i].text)).ok)
                    report("local variable '" + t_[i + 1].text + "' in '" + f.name + "' has annotations: only globals take them", i + 2);
            }
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findLocalDeclarationErrors(const EffectSyntax& syntax, const SourceMap& map) {
    LocalDeclarationRules check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
