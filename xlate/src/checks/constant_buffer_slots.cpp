// At most 14 constant buffers per shader (D3D10/11's slots; fxc X4567), counted as fxc counts
// them for each shader it compiles (each pass's entry point, an effect's shader variables, a loose
// file's /E): a `register(bN)` reserves its slot whether the shader reads the cbuffer or not
// (vkd3d's cbuffer.shader_test), cbuffers written with one register share it (Wicked Engine's and
// RenderDoc's headers declare a dozen cbuffers on b0..b3 for shaders that read one or two); a
// cbuffer without a register takes a slot only when the shader reads a member of it, $Globals when
// it reads a number outside the cbuffers, $Params when its entry takes uniform parameters. An
// fx_5_0 effect whose techniques read twenty cbuffers between them compiles as long as each shader
// reads fourteen at most (a D3D11 course's effects that include 00_Global.fx, 00_Light.fx ...).
#include <algorithm>
#include <set>

#include "checks/fxc_checks.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

class ConstantBufferSlots : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        std::set<const FxFunction*> judged;
        for (const CompiledEntry& e : compiledEntries()) {
            if (e.profile.major < 4 || !judged.insert(e.function).second) continue;
            judge(*e.function);
        }
    }

private:
    void judge(const FxFunction& entry) {
        const std::vector<const FxFunction*> reached = reachableFrom(entry);
        std::set<int> registers;
        size_t count = 0;
        for (size_t k = 0; k < syntax_.cbuffers.size(); ++k) {
            int reg = k < syntax_.cbufferRegisters.size() ? syntax_.cbufferRegisters[k] : -1;
            if (reg >= 0) registers.insert(reg);
            else count += reads(reached, [&](const FxGlobal& g) { return g.cbuffer == syntax_.cbuffers[k]; });
        }
        count += registers.size();
        const bool globals = reads(reached, [&](const FxGlobal& g) {
            bool constant = std::find(g.modifiers.begin(), g.modifiers.end(), "static") != g.modifiers.end();
            return g.cbuffer.empty() && !constant && !g.isStringParameter && describeBasicType(syntax_.resolveType(g.type)).ok;
        });
        bool params = false;
        for (const auto& p : entry.parameters)
            params |= std::find(p.modifiers.begin(), p.modifiers.end(), "uniform") != p.modifiers.end();
        count += globals + params;
        if (count > 14)
            report("'" + entry.name + "' needs " + std::to_string(count) + " constant buffers (its cbuffers" + (globals ? ", $Globals" : "") +
                       (params ? ", $Params" : "") + "); D3D has 14 slots (fxc X4567)",
                   entry.token);
    }

    // Whether a reached function, or any struct's member function (their calls are not followed),
    // names a global that `wanted` picks.
    template <class Wanted>
    bool reads(const std::vector<const FxFunction*>& reached, Wanted wanted) const {
        std::set<std::string> names;
        for (const auto& g : syntax_.globals)
            if (wanted(g)) names.insert(g.name);
        if (names.empty()) return false;
        auto mentions = [&](size_t begin, size_t end) {
            for (size_t i = begin; i < end && i < t_.size(); ++i)
                if (t_[i].isIdent() && names.count(t_[i].text) && !(i > 0 && t_[i - 1].is("."))) return true;
            return false;
        };
        for (const FxFunction* f : reached)
            if (mentions(f->body.begin, f->body.end)) return true;
        for (const TokenSpan& b : syntax_.memberFunctionBodies)
            if (mentions(b.begin, b.end)) return true;
        return false;
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findConstantBufferSlotErrors(const EffectSyntax& syntax, const SourceMap& map) {
    ConstantBufferSlots check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
