// See rounding.h.
#include "spirv/rounding.h"

namespace fxport::xlate {

// Test: xlate RealworldEighthWave.RoundOfDx9StyleSourceRoundsHalvesToEven.
bool roundHalvesToEven(ParsedSpirv& m) {
    constexpr std::uint32_t kRound = 1, kRoundEven = 2;
    if (!m.has({spv_op::ExtInst})) return false;
    const std::uint32_t std450 = m.glslStd450();
    bool changed = false;
    for (SpirvInstruction& in : m.instructions) {
        // %r = OpExtInst %type %std450 Round %x
        if (in.opcode() != spv_op::ExtInst || in.words.size() != 6 || in.words[3] != std450 || in.words[4] != kRound) continue;
        in.words[4] = kRoundEven;
        changed = true;
    }
    return changed;
}

}  // namespace fxport::xlate
