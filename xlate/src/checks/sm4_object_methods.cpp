// Texture methods that D3D9 has no instruction for: below shader model 4, fxc maps a texture's
// Sample, SampleLevel, SampleBias and SampleGrad onto tex2D/tex2Dlod/tex2Dbias/tex2Dgrad of a
// combined sampler, but Load, GetDimensions, the Gather family, the comparison samplers,
// CalculateLevelOfDetail and GetSamplePosition it refuses in a vs_/ps_2_x or 3_0 shader (vkd3d's
// combined-samplers: `tex[0][0].Load(...)` at sm < 4). glslang compiles them for GL, so the rule is
// checked here, on the functions each SM 1-3 entry reaches.
#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

bool isSm4OnlyMethod(const std::string& s) {
    static const char* const kMethods[] = {"Load", "GetDimensions", "Gather", "GatherRed", "GatherGreen", "GatherBlue", "GatherAlpha",
                                           "GatherCmp", "GatherCmpRed", "GatherCmpGreen", "GatherCmpBlue", "GatherCmpAlpha", "SampleCmp",
                                           "SampleCmpLevelZero", "CalculateLevelOfDetail", "CalculateLevelOfDetailUnclamped",
                                           "GetSamplePosition"};
    for (const char* m : kMethods)
        if (s == m) return true;
    return false;
}

class Sm4ObjectMethods : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& e : compiledEntries()) {
            if (e.profile.major >= 4) continue;
            for (const FxFunction* f : reachableFrom(*e.function))
                for (size_t i = f->body.begin; i + 3 < f->body.end; ++i) {
                    if (!isTexture(t_[i].text) || (i > 0 && t_[i - 1].is("."))) continue;
                    size_t dot = i + 1;
                    while (t_[dot].is("[")) dot = closing(dot) + 1;  // tex[i][j].Load
                    if (dot + 2 >= f->body.end || !t_[dot].is(".") || !isSm4OnlyMethod(t_[dot + 1].text) || !t_[dot + 2].is("(")) continue;
                    report("'" + t_[dot + 1].text + "' of texture '" + t_[i].text + "' has no " + e.profile.name +
                                        " instruction: it needs shader model 4.0 or later (fxc X4532)",
                           dot + 1);
                }
        }
    }

private:
    bool isTexture(const std::string& name) const {
        for (const FxTexture& tex : syntax_.textures)
            if (tex.name == name) return true;
        return false;
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findSm4ObjectMethodErrors(const EffectSyntax& syntax, const SourceMap& map) {
    Sm4ObjectMethods check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
