// A uniform's initial value is a default the application may override, stored in the effect as
// data: fxc wants a literal expression there (vkd3d's default-values pins it), so an initializer
// that reads another uniform or a resource is refused ("initial value must be a literal
// expression"). glslang takes it as a computed global. Static globals are computed in the shader
// and may read anything; they are not judged.
#include <algorithm>

#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

bool has(const std::vector<std::string>& modifiers, const char* m) {
    return std::find(modifiers.begin(), modifiers.end(), m) != modifiers.end();
}

class UniformInitializers : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& g : syntax_.globals) {
            if (has(g.modifiers, "static") || g.isStringParameter || g.initializer.empty()) continue;
            for (size_t i = g.initializer.begin; i < g.initializer.end && i < t_.size(); ++i) {
                if (!t_[i].isIdent() || (i > 0 && t_[i - 1].is(".")) || tok(i + 1).is("(")) continue;
                if (const std::string* what = readsUniform(t_[i].text, g.name))
                    report("initial value of '" + g.name + "' must be a literal expression: it reads " + *what + " '" + t_[i].text + "'", i);
            }
        }
    }

private:
    // "uniform" / "texture" / "sampler" when `name` is one (other than `self`), else nothing.
    const std::string* readsUniform(const std::string& name, const std::string& self) const {
        static const std::string uniform = "uniform", texture = "texture", sampler = "sampler";
        if (name == self) return nullptr;
        for (const auto& other : syntax_.globals)
            if (other.name == name && !has(other.modifiers, "static") && !other.isStringParameter) return &uniform;
        if (syntax_.findTexture(name)) return &texture;
        if (syntax_.findSampler(name)) return &sampler;
        return nullptr;
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findUniformInitializerErrors(const EffectSyntax& syntax, const SourceMap& map) {
    UniformInitializers check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
