// See ps2_equality.h.
#include "spirv/ps2_equality.h"

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kOpFSub = 131, kOpFMul = 133, kOpFOrdEqual = 180, kOpFUnordNotEqual = 183;

bool isFloat32(const ParsedSpirv& m, std::uint32_t type) {
    const SpirvInstruction* c = m.definition(m.components(type).first);
    return c && c->opcode() == spv_op::TypeFloat && c->word(2) == 32;
}

}  // namespace

// Test: runtime HlslSm3Floats.Ps2EqualityIsASquaredDifference, conformance float-comparison L92.
bool equalityBySquaredDifference(ParsedSpirv& m) {
    if (!m.has({kOpFOrdEqual, kOpFOrdEqual + 1, kOpFOrdEqual + 2, kOpFUnordNotEqual})) return false;
    bool changed = false;
    m.rewrite([&](const SpirvInstruction& in, std::vector<SpirvInstruction>& out) {
        const std::uint32_t op = in.opcode();
        if (op < kOpFOrdEqual || op > kOpFUnordNotEqual || in.words.size() != 5) return out.push_back(in);
        const std::uint32_t type = m.typeOf(in.words[3]);
        if (!isFloat32(m, type) || m.typeOf(in.words[4]) != type) return out.push_back(in);
        SpirvInstruction difference = m.value(kOpFSub, type, {in.words[3], in.words[4]});
        SpirvInstruction square = m.value(kOpFMul, type, {difference.words[2], difference.words[2]});
        SpirvInstruction r = in;  // the same comparison, of the square with 0
        r.words[3] = square.words[2];
        r.words[4] = m.splatConstant(type, 0);
        out.push_back(std::move(difference));
        out.push_back(std::move(square));
        out.push_back(std::move(r));
        changed = true;
    });
    return changed;
}

}  // namespace fxport::xlate
