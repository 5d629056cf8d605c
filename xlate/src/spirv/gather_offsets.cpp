// See gather_offsets.h: OpImage(Dref)Gather with ConstOffsets as four gathers with ConstOffset.
#include "spirv/gather_offsets.h"

#include <array>
#include <optional>

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kImageGather = 96, kImageDrefGather = 97, kCompositeConstruct = 80, kCompositeExtract = 81;
constexpr std::uint32_t kConstantComposite = 44, kConstantNull = 46, kTypeArray = 28;
constexpr std::uint32_t kBias = 0x1, kLod = 0x2, kGrad = 0x4, kConstOffset = 0x8, kOffset = 0x10, kConstOffsets = 0x20;

// Words of the image operands before ConstOffsets': Bias, Lod (one id each), Grad (two),
// ConstOffset and Offset (one each).
size_t operandsBeforeConstOffsets(std::uint32_t mask) {
    return ((mask & kBias) ? 1 : 0) + ((mask & kLod) ? 1 : 0) + ((mask & kGrad) ? 2 : 0) + ((mask & kConstOffset) ? 1 : 0) +
           ((mask & kOffset) ? 1 : 0);
}

// The four offset constants of a ConstOffsets operand (an array constant, or its null).
std::optional<std::array<std::uint32_t, 4>> offsetConstants(ParsedSpirv& m, std::uint32_t offsets) {
    const SpirvInstruction* def = m.definition(offsets);
    if (!def) return std::nullopt;
    if (def->opcode() == kConstantComposite && def->words.size() == 7) return std::array<std::uint32_t, 4>{def->words[3], def->words[4], def->words[5], def->words[6]};
    if (def->opcode() != kConstantNull) return std::nullopt;
    const SpirvInstruction* array = m.definition(def->word(1));
    if (!array || array->opcode() != kTypeArray) return std::nullopt;
    std::uint32_t zero = m.splatConstant(array->word(2), 0);
    return std::array<std::uint32_t, 4>{zero, zero, zero, zero};
}

}  // namespace

bool gatherOffsetsAsFourGathers(ParsedSpirv& m) {
    bool changed = false;
    m.rewrite([&](const SpirvInstruction& inst, std::vector<SpirvInstruction>& out) {
        // OpImage(Dref)Gather type id sampledImage coordinate component|dref mask operands...
        const auto& w = inst.words;
        const bool gather = inst.opcode() == kImageGather || inst.opcode() == kImageDrefGather;
        if (!gather || w.size() < 8 || !(w[6] & kConstOffsets) || (w[6] & kConstOffset)) return out.push_back(inst);
        const size_t at = 7 + operandsBeforeConstOffsets(w[6]);
        std::optional<std::array<std::uint32_t, 4>> offsets = at < w.size() ? offsetConstants(m, w[at]) : std::nullopt;
        std::uint32_t scalar = m.components(w[1]).first;
        if (!offsets || !scalar) return out.push_back(inst);
        std::vector<std::uint32_t> parts;
        for (std::uint32_t k = 0; k < 4; ++k) {
            SpirvInstruction one = m.value(inst.opcode(), w[1], {});
            std::vector<std::uint32_t> words(w.begin(), w.end());
            words[2] = one.words[2];
            words[6] = (w[6] & ~kConstOffsets) | kConstOffset;  // ConstOffset sits where ConstOffsets was
            words[at] = (*offsets)[k];
            out.push_back({std::move(words)});
            out.push_back(m.value(kCompositeExtract, scalar, {one.words[2], k}));
            parts.push_back(out.back().words[2]);
        }
        out.push_back({{spirvFirstWord(kCompositeConstruct, 7), w[1], w[2], parts[0], parts[1], parts[2], parts[3]}});
        changed = true;
    });
    return changed;
}

}  // namespace fxport::xlate
