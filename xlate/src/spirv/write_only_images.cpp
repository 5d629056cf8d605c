// See write_only_images.h.
#include "spirv/write_only_images.h"

#include <set>

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kCapability = 17, kTypeImage = 25, kTypePointer = 32, kImageTexelPointer = 60, kImageRead = 98,
                        kImageSparseRead = 320;
constexpr std::uint32_t kStorageImageWriteWithoutFormat = 56, kSampledStorage = 2, kFormatUnknown = 0;

}  // namespace

bool writeOnlyImagesWithoutFormat(ParsedSpirv& m) {
    std::set<std::uint32_t> formatted;  // storage image types with a format
    for (const SpirvInstruction& in : m.instructions)
        if (in.opcode() == kTypeImage && in.word(7) == kSampledStorage && in.word(8) != kFormatUnknown) formatted.insert(in.word(1));
    if (formatted.empty()) return false;
    std::set<std::uint32_t> read;
    for (const SpirvInstruction& in : m.instructions) {
        if (in.opcode() == kImageRead || in.opcode() == kImageSparseRead) read.insert(m.typeOf(in.word(3)));
        if (in.opcode() == kImageTexelPointer)  // an atomic's image: a pointer to it
            if (const SpirvInstruction* pointer = m.definition(m.typeOf(in.word(3))); pointer && pointer->opcode() == kTypePointer)
                read.insert(pointer->word(3));
    }
    bool changed = false, capability = false;
    for (SpirvInstruction& in : m.instructions) {
        capability |= in.opcode() == kCapability && in.word(1) == kStorageImageWriteWithoutFormat;
        if (in.opcode() == kTypeImage && formatted.count(in.word(1)) && !read.count(in.word(1))) {
            in.words[8] = kFormatUnknown;
            changed = true;
        }
    }
    if (changed && !capability) {  // before the module's first capability
        bool placed = false;
        m.rewrite([&](const SpirvInstruction& in, std::vector<SpirvInstruction>& out) {
            if (!placed && in.opcode() == kCapability) out.push_back({{spirvFirstWord(kCapability, 2), kStorageImageWriteWithoutFormat}});
            placed |= in.opcode() == kCapability;
            out.push_back(in);
        });
    }
    return changed;
}

}  // namespace fxport::xlate
