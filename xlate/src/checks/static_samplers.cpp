// fxc refuses to sample through a `static` sampler declared without a value: it binds no sampler
// to the shader (vkd3d's static-initializer pins it, for SM 1-style tex2D and SM 4 Sample alike;
// the sample's result need not be used).
#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

bool isSamplerType(const std::string& s) {
    return s == "sampler" || s == "sampler1D" || s == "sampler2D" || s == "sampler3D" || s == "samplerCUBE" || s == "SamplerState" ||
           s == "SamplerComparisonState";
}

class StaticSamplers : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (size_t i = 0; i + 3 < t_.size(); ++i) {
            if (!t_[i].is("static") || !isSamplerType(t_[i + 1].text) || !t_[i + 2].isIdent() || !t_[i + 3].is(";") || inFunction(i)) continue;
            if (usedAsSampler(t_[i + 2].text))
                report("static sampler '" + t_[i + 2].text + "' has no value: fxc samples only through a sampler it binds", i + 2);
        }
    }

private:
    // `name` as an argument of a call in some function (tex2D(s, uv), t.Sample(s, uv)).
    bool usedAsSampler(const std::string& name) const {
        for (const auto& f : syntax_.functions)
            for (size_t k = f.body.begin + 1; k + 1 < f.body.end; ++k)
                if (t_[k].is(name) && (t_[k - 1].is("(") || t_[k - 1].is(",")) && (t_[k + 1].is(",") || t_[k + 1].is(")"))) return true;
        return false;
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findStaticSamplerErrors(const EffectSyntax& syntax, const SourceMap& map) {
    StaticSamplers check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
