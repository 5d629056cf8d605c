// Declarations fxc refuses by their form, where glslang takes them:
//  - `struct { ... };` with neither a name nor a variable declares nothing (fxc: a syntax error;
//    vkd3d's struct-syntax pins it);
//  - `null` is no keyword (NULL is): a value named `null` that nothing declares is an undeclared
//    identifier (X3004; vkd3d's null), except as a pass's state value, where the effect framework
//    takes `null` (the DirectX SDK samples' `VertexShader = null;`).
#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

class DeclarationForms : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        const bool nullDeclared = declares("null");
        for (size_t i = 0; i + 1 < t_.size(); ++i) {
            if (t_[i].is("struct") && t_[i + 1].is("{") && (i == 0 || !t_[i - 1].is("typedef"))) {
                size_t close = closing(i + 1);
                if (tok(close + 1).is(";")) report("an anonymous struct that declares no variable declares nothing (fxc refuses it)", i);
            }
            if (t_[i].isIdent() && t_[i].is("null") && !nullDeclared && i > 0 && (t_[i - 1].is("=") || t_[i - 1].is("(") || t_[i - 1].is(",")) &&
                !inPassState(i))
                report("undeclared identifier 'null' (NULL is the keyword; fxc X3004)", i);
        }
    }

private:
    // A pass's state value (`VertexShader = null;`): the effect framework reads its keywords in any
    // case, and the DirectX SDK's own samples spell it so.
    bool inPassState(size_t i) const {
        for (const auto& t : syntax_.techniques)
            for (const auto& p : t.passes)
                for (const auto& a : p.assignments)
                    if (i >= a.value.begin && i < a.value.end) return true;
        return false;
    }

    // `T name` anywhere: a variable, a parameter or a typedef of that name.
    bool declares(const std::string& name) const {
        for (size_t i = 1; i < t_.size(); ++i)
            if (t_[i].is(name) && t_[i - 1].isIdent()) return true;
        return false;
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findDeclarationFormErrors(const EffectSyntax& syntax, const SourceMap& map) {
    DeclarationForms check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
