// What fxc checks in the effect framework's shader-object values, loose shaders included (it parses
// them there and drops them after); vkd3d's effect-compile and constructgswithso pin them:
//  - `compile ps_2_0 f(1, 2, 3)` passes literals to f's uniform parameters: no more literals than
//    the overload with most uniform parameters takes;
//  - a shader variable is not initialised from a number (`PixelShader ps = 42;`), nor from another
//    shader variable (`PixelShader ps2 = ps1;`: "initializer must be a literal expression", as for
//    any uniform's default value, uniform_initializers.cpp);
//  - ConstructGSWithSO takes 2 arguments (shader, declaration: Effects 10) or 6 (shader, four
//    stream declarations, rasterized stream: Effects 11).
#include <algorithm>

#include "checks/fxc_checks.h"
#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

bool isShaderType(const std::string& s) {
    for (const char* n : {"VertexShader", "PixelShader", "GeometryShader", "HullShader", "DomainShader", "ComputeShader"})
        if (iequals(s, n)) return true;
    return false;
}

class EffectObjectValues : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& tech : syntax_.techniques)
            for (const auto& pass : tech.passes)
                for (const auto& a : pass.assignments)
                    if (!a.value.empty() && tok(a.value.begin).is("compile")) literalArguments(parseShaderExpr(syntax_, a.value));
        for (const auto& v : syntax_.shaderVariables)
            for (const auto& e : v.elements) literalArguments(e);
        for (size_t i = 0; i + 4 < t_.size(); ++i) {
            if (isShaderType(t_[i].text) && t_[i + 1].isIdent() && t_[i + 2].is("=") && t_[i + 3].kind == Token::Kind::Number && t_[i + 4].is(";"))
                report("shader variable '" + t_[i + 1].text + "' cannot be initialised from the number " + t_[i + 3].text, i + 3);
            if (isShaderType(t_[i].text) && t_[i + 1].isIdent() && t_[i + 2].is("=") && t_[i + 3].isIdent() && t_[i + 4].is(";") &&
                isShaderVariable(t_[i + 3].text))
                report("shader variable '" + t_[i + 1].text + "' cannot be initialised from the variable '" + t_[i + 3].text +
                           "': the initial value must be a literal expression",
                       i + 3);
            if (t_[i].is("ConstructGSWithSO") && t_[i + 1].is("(")) streamOutputArguments(i);
        }
    }

private:
    bool isShaderVariable(const std::string& name) const {
        for (const auto& v : syntax_.shaderVariables)
            if (v.name == name) return true;
        return false;
    }

    void literalArguments(const FxShaderExpr& e) {
        if (e.kind != FxShaderExpr::Kind::Compile || trim(e.arguments).empty()) return;
        size_t given = 1;
        int depth = 0;
        for (char c : e.arguments) {
            depth += c == '(' ? 1 : c == ')' ? -1 : 0;
            if (c == ',' && depth == 0) ++given;
        }
        size_t most = 0;
        bool any = false;
        for (const auto& f : syntax_.functions) {
            if (f.name != e.entry) continue;
            any = true;
            size_t uniforms = std::count_if(f.parameters.begin(), f.parameters.end(), [](const FxParameter& p) {
                return std::find(p.modifiers.begin(), p.modifiers.end(), "uniform") != p.modifiers.end();
            });
            most = std::max(most, uniforms);
        }
        if (any && given > most)
            report("'compile " + e.profile + " " + e.entry + "(...)' passes " + std::to_string(given) + " arguments, but '" + e.entry + "' takes " +
                       std::to_string(most) + " uniform parameters",
                   e.token);
    }

    void streamOutputArguments(size_t at) {
        size_t close = closing(at + 1), count = close == at + 2 ? 0 : 1;
        for (size_t j = at + 2; j < close; ++j) {
            if (t_[j].is("(") || t_[j].is("{") || t_[j].is("[")) j = closing(j);
            else if (t_[j].is(",")) ++count;
        }
        if (count != 2 && count != 6)
            report("ConstructGSWithSO takes 2 arguments (shader, output declaration) or 6 (shader, four declarations, rasterized stream), not " +
                       std::to_string(count),
                   at);
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findEffectObjectValueErrors(const EffectSyntax& syntax, const SourceMap& map) {
    EffectObjectValues check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
