// See legacy_division.h.
#include "spirv/legacy_division.h"

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kOpLogicalOr = 166, kOpLogicalAnd = 167, kOpSelect = 169, kOpFOrdEqual = 180, kGlslStd450FAbs = 4, kInfinity = 0x7f800000u;

bool isFloat32(const ParsedSpirv& m, std::uint32_t type) {
    const SpirvInstruction* c = m.definition(m.components(type).first);
    return c && c->opcode() == spv_op::TypeFloat && c->word(2) == 32;
}

}  // namespace

// Test: runtime HlslSm3Floats.ZeroOverZeroIsZero, conformance float-comparison L60.
bool divisionAsRcpTimes(ParsedSpirv& m) {
    if (!m.has({spv_op::FDiv})) return false;
    bool changed = false;
    m.rewrite([&](const SpirvInstruction& in, std::vector<SpirvInstruction>& out) {
        if (in.opcode() != spv_op::FDiv || in.words.size() != 5 || !isFloat32(m, in.words[1])) return out.push_back(in);
        const std::uint32_t type = in.words[1], a = in.words[3], b = in.words[4], boolType = m.boolTypeLike(type);
        const std::uint32_t zero = m.splatConstant(type, 0), infinity = m.splatConstant(type, kInfinity);
        std::vector<SpirvInstruction> added;
        auto add = [&](std::uint32_t op, std::uint32_t resultType, const std::vector<std::uint32_t>& operands) {
            added.push_back(m.value(op, resultType, operands));
            return added.back().words[2];
        };
        auto infinite = [&](std::uint32_t x) {
            return add(kOpFOrdEqual, boolType, {add(spv_op::ExtInst, type, {m.glslStd450(), kGlslStd450FAbs, x}), infinity});
        };
        const std::uint32_t zeros = add(kOpLogicalAnd, boolType, {add(kOpFOrdEqual, boolType, {a, zero}), add(kOpFOrdEqual, boolType, {b, zero})});
        const std::uint32_t infinities = add(kOpLogicalAnd, boolType, {infinite(a), infinite(b)});
        const std::uint32_t either = add(kOpLogicalOr, boolType, {zeros, infinities});
        const std::uint32_t quotient = add(spv_op::FDiv, type, {a, b});
        SpirvInstruction r = in;  // keeps the result id
        r.words = {spirvFirstWord(kOpSelect, 6), type, in.words[2], either, zero, quotient};
        for (SpirvInstruction& i : added) out.push_back(std::move(i));
        out.push_back(std::move(r));
        changed = true;
    });
    return changed;
}

}  // namespace fxport::xlate
