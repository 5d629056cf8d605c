// `noise(x)` is an intrinsic of texture shaders (tx_1_0, run on the CPU by D3DXFillTextureTX)
// only: no vertex, pixel, geometry, hull, domain or compute profile has an instruction for it, and
// fxc refuses a call a compiled shader reaches (an unreached one is never compiled: vkd3d's
// noise.shader_test). glslang's HLSL front end takes the call and then crashes (SIGSEGV) on it,
// so the rule is checked here, on the functions each compiled entry reaches. A function of the
// effect's own named `noise` (OpenXRay's shaders could have one) is called instead: not judged.
#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

class TextureShaderIntrinsics : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const FxFunction& f : syntax_.functions)
            if (f.name == "noise") return;
        for (const auto& e : compiledEntries())
            for (const FxFunction* f : reachableFrom(*e.function))
                for (size_t i = f->body.begin; i + 1 < f->body.end; ++i)
                    if (t_[i].is("noise") && t_[i + 1].is("(") && (i == 0 || !t_[i - 1].is(".")))
                        report("'noise' is a texture-shader (tx_1_0) intrinsic: " + e.profile.name + " has no instruction for it", i);
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findTextureShaderIntrinsicErrors(const EffectSyntax& syntax, const SourceMap& map) {
    TextureShaderIntrinsics check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
