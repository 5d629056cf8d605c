// See fetch_offsets.h: a variable texel offset of OpImageFetch added to the coordinate.
#include "spirv/fetch_offsets.h"

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kImageFetch = 95, kIAdd = 128, kCompositeConstruct = 80, kCompositeExtract = 81;
constexpr std::uint32_t kBias = 0x1, kLod = 0x2, kGrad = 0x4, kConstOffset = 0x8, kOffset = 0x10;

std::uint32_t firstWord(std::uint32_t opcode, size_t count) { return (std::uint32_t(count) << 16) | opcode; }

// Words of the image operands before Offset's: Bias, Lod (one id each), Grad (two), ConstOffset (one).
size_t operandsBeforeOffset(std::uint32_t mask) {
    return ((mask & kBias) ? 1 : 0) + ((mask & kLod) ? 1 : 0) + ((mask & kGrad) ? 2 : 0) + ((mask & kConstOffset) ? 1 : 0);
}

}  // namespace

bool fetchOffsetsIntoCoordinates(ParsedSpirv& m) {
    bool changed = false;
    m.rewrite([&](const SpirvInstruction& inst, std::vector<SpirvInstruction>& out) {
        // OpImageFetch type id image coordinate mask operands...
        const auto& w = inst.words;
        if (inst.opcode() != kImageFetch || w.size() < 7 || !(w[5] & kOffset)) return out.push_back(inst);
        size_t at = 6 + operandsBeforeOffset(w[5]);
        if (at >= w.size()) return out.push_back(inst);
        std::uint32_t coordinate = w[4], offset = w[at];
        std::uint32_t coordinateType = m.typeOf(coordinate);
        auto [scalar, coordinateCount] = m.components(coordinateType);
        std::uint32_t offsetCount = m.components(m.typeOf(offset)).second;
        if (!coordinateType || offsetCount > coordinateCount) return out.push_back(inst);
        if (offsetCount < coordinateCount) {  // an array's layer (or a level) is not offset
            std::vector<std::uint32_t> parts;
            for (std::uint32_t k = 0; k < coordinateCount; ++k) {
                if (k >= offsetCount) parts.push_back(m.constant(scalar, 0));
                else if (offsetCount == 1) parts.push_back(offset);
                else {
                    out.push_back(m.value(kCompositeExtract, scalar, {offset, k}));
                    parts.push_back(out.back().words[2]);
                }
            }
            out.push_back(m.value(kCompositeConstruct, coordinateType, parts));
            offset = out.back().words[2];
        }
        SpirvInstruction sum = m.value(kIAdd, coordinateType, {coordinate, offset});
        const std::uint32_t mask = w[5] & ~kOffset;
        std::vector<std::uint32_t> fetch{0, w[1], w[2], w[3], sum.words[2]};
        if (mask) {  // no operand left: no mask either
            fetch.push_back(mask);
            for (size_t k = 6; k < w.size(); ++k)
                if (k != at) fetch.push_back(w[k]);
        }
        fetch[0] = firstWord(kImageFetch, fetch.size());
        out.push_back(std::move(sum));
        out.push_back({std::move(fetch)});
        changed = true;
    });
    return changed;
}

}  // namespace fxport::xlate
