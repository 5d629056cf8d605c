// See spirv_negated_comparisons.h.
#include "spirv/spirv_negated_comparisons.h"

#include <spirv-tools/libspirv.h>

#include <map>

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kOpLogicalNot = 168;
// Each ordered relational comparison; its unordered twin is the next opcode.
constexpr std::uint32_t kOpFOrdLessThan = 184, kOpFOrdGreaterThan = 186, kOpFOrdLessThanEqual = 188, kOpFOrdGreaterThanEqual = 190;

bool isOrderedRelational(std::uint32_t op) {
    return op == kOpFOrdLessThan || op == kOpFOrdGreaterThan || op == kOpFOrdLessThanEqual || op == kOpFOrdGreaterThanEqual;
}

struct Scan {
    const std::uint32_t* base = nullptr;
    std::map<std::uint32_t, size_t> comparisons;  // result id -> offset of its ordered comparison
    std::map<std::uint32_t, int> uses;            // id -> operands naming it
    std::vector<std::uint32_t> negated;           // operands of OpLogicalNot
};

}  // namespace

void negatedComparisonsAsOpposites(std::vector<std::uint32_t>& words) {
    Scan scan;
    scan.base = words.data();
    auto onInstruction = [](void* user, const spv_parsed_instruction_t* inst) -> spv_result_t {
        auto* s = static_cast<Scan*>(user);
        for (std::uint16_t k = 0; k < inst->num_operands; ++k) {
            const spv_parsed_operand_t& o = inst->operands[k];
            if (o.type == SPV_OPERAND_TYPE_ID) ++s->uses[inst->words[o.offset]];
        }
        if (isOrderedRelational(inst->opcode)) s->comparisons[inst->result_id] = size_t(inst->words - s->base);
        if (inst->opcode == kOpLogicalNot && inst->num_words == 4) s->negated.push_back(inst->words[3]);
        return SPV_SUCCESS;
    };
    spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_0);
    spv_result_t r = spvBinaryParse(context, &scan, words.data(), words.size(), nullptr, onInstruction, nullptr);
    spvContextDestroy(context);
    if (r != SPV_SUCCESS) return;
    for (std::uint32_t id : scan.negated) {
        auto c = scan.comparisons.find(id);
        if (c == scan.comparisons.end() || scan.uses[id] != 1) continue;
        words[c->second] += 1;  // the unordered twin, same operands
    }
}

}  // namespace fxport::xlate
