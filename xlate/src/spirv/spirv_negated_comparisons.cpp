// See spirv_negated_comparisons.h.
#include "spirv/spirv_negated_comparisons.h"

#include <map>

namespace fxport::xlate {

namespace {

// Each ordered relational comparison; its unordered twin is the next opcode.
constexpr std::uint32_t kOpFOrdLessThan = 184, kOpFOrdGreaterThan = 186, kOpFOrdLessThanEqual = 188, kOpFOrdGreaterThanEqual = 190;

bool isOrderedRelational(std::uint32_t op) {
    return op == kOpFOrdLessThan || op == kOpFOrdGreaterThan || op == kOpFOrdLessThanEqual || op == kOpFOrdGreaterThanEqual;
}

}  // namespace

bool negatedComparisonsAsOpposites(ParsedSpirv& m) {
    if (!m.has({spv_op::LogicalNot})) return false;
    std::map<std::uint32_t, size_t> comparisons;  // result id -> index of its ordered comparison
    std::map<std::uint32_t, int> uses;            // id -> operands naming it
    std::vector<std::uint32_t> negated;           // operands of OpLogicalNot
    for (size_t i = 0; i < m.instructions.size(); ++i) {
        const SpirvInstruction& inst = m.instructions[i];
        const SpirvInstructionIds& ids = m.ids(i);
        for (std::uint16_t k : ids.operands) ++uses[inst.words[k]];
        if (isOrderedRelational(inst.opcode())) comparisons[ids.result] = i;
        if (inst.opcode() == spv_op::LogicalNot && inst.words.size() == 4) negated.push_back(inst.words[3]);
    }
    bool changed = false;
    for (std::uint32_t id : negated) {
        auto c = comparisons.find(id);
        if (c == comparisons.end() || uses[id] != 1) continue;
        m.instructions[c->second].words[0] += 1;  // the unordered twin, same operands
        changed = true;
    }
    return changed;
}

}  // namespace fxport::xlate
