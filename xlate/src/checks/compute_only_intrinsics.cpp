// Group barriers exist in compute shaders only: fxc refuses GroupMemoryBarrier, the
// ...WithGroupSync barriers and AllMemoryBarrier in a vertex, geometry or pixel shader (vkd3d's
// barriers pins them; DeviceMemoryBarrier alone is allowed there). Judged on the functions each
// compiled entry reaches.
#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

bool isGroupBarrier(const std::string& s) {
    return s == "GroupMemoryBarrier" || s == "GroupMemoryBarrierWithGroupSync" || s == "DeviceMemoryBarrierWithGroupSync" ||
           s == "AllMemoryBarrier" || s == "AllMemoryBarrierWithGroupSync";
}

class ComputeOnlyIntrinsics : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& e : compiledEntries()) {
            if (e.profile.stage != ShaderStage::Vertex && e.profile.stage != ShaderStage::Pixel && e.profile.stage != ShaderStage::Geometry) continue;
            for (const FxFunction* f : reachableFrom(*e.function))
                for (size_t i = f->body.begin; i + 1 < f->body.end; ++i)
                    if (t_[i].isIdent() && isGroupBarrier(t_[i].text) && t_[i + 1].is("("))
                        report("'" + t_[i].text + "' is for compute shaders only, not " + e.profile.name, i);
        }
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findComputeOnlyIntrinsicErrors(const EffectSyntax& syntax, const SourceMap& map) {
    ComputeOnlyIntrinsics check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
