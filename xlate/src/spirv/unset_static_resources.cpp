// See unset_static_resources.h.
#include "spirv/unset_static_resources.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <regex>

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kOpTypeImage = 25, kOpTypeSampler = 26, kOpTypeSampledImage = 27, kOpTypeArray = 28,
                        kOpTypeRuntimeArray = 29, kOpTypePointer = 32, kOpVariable = 59, kOpLoad = 61, kOpStore = 62,
                        kOpCopyMemory = 63, kOpAccessChain = 65, kOpInBoundsAccessChain = 66, kStoragePrivate = 6;

bool isResourceType(const ParsedSpirv& m, std::uint32_t type, int depth = 0) {
    const SpirvInstruction* d = m.definition(type);
    if (!d || depth > 8) return false;
    switch (d->opcode()) {
    case kOpTypeImage:
    case kOpTypeSampler:
    case kOpTypeSampledImage: return true;
    case kOpTypeArray:
    case kOpTypeRuntimeArray: return isResourceType(m, d->word(2), depth + 1);
    default: return false;
    }
}

// The Private resource variables without an initializer: id -> whether read, whether written.
struct Use {
    bool read = false, written = false;
};

std::map<std::uint32_t, Use> unsetResourceVariables(const ParsedSpirv& m) {
    std::map<std::uint32_t, Use> out;
    for (const auto& inst : m.instructions) {
        if (inst.opcode() != kOpVariable || inst.words.size() != 4 || inst.word(3) != kStoragePrivate) continue;
        const SpirvInstruction* pointer = m.definition(inst.word(1));
        if (pointer && pointer->opcode() == kOpTypePointer && isResourceType(m, pointer->word(3))) out[inst.word(2)] = {};
    }
    return out;
}

}  // namespace

std::string staticResourceReadWithoutValue(const std::vector<std::uint32_t>& words) {
    ParsedSpirv m;
    if (!m.parse(words)) return "";
    std::map<std::uint32_t, Use> vars = unsetResourceVariables(m);
    if (vars.empty()) return "";
    std::map<std::uint32_t, std::uint32_t> rootOf;  // access chain -> the variable it points into
    auto root = [&](std::uint32_t id) {
        auto chain = rootOf.find(id);
        return chain == rootOf.end() ? id : chain->second;
    };
    for (const auto& inst : m.instructions) {
        const std::uint32_t op = inst.opcode();
        if ((op == kOpAccessChain || op == kOpInBoundsAccessChain) && vars.count(root(inst.word(3)))) rootOf[inst.word(2)] = root(inst.word(3));
        if (op == kOpLoad && vars.count(root(inst.word(3)))) vars[root(inst.word(3))].read = true;
        if ((op == kOpStore || op == kOpCopyMemory) && vars.count(root(inst.word(1)))) vars[root(inst.word(1))].written = true;
        if (op == kOpCopyMemory && vars.count(root(inst.word(2)))) vars[root(inst.word(2))].read = true;
    }
    for (const auto& [id, use] : vars) {
        if (!use.read || use.written) continue;
        for (const auto& inst : m.instructions)
            if (inst.opcode() == spv_op::Name && inst.word(1) == id) {
                const auto* bytes = reinterpret_cast<const char*>(inst.words.data() + 2);
                return std::string(bytes, strnlen(bytes, (inst.words.size() - 2) * 4));
            }
        return "(unnamed)";
    }
    return "";
}

int staticDeclarationLine(const std::string& source, const std::string& name) {
    const std::regex declaration("\\bstatic\\b[^;{}()]*\\b" + name + "\\b");
    std::smatch m;
    if (!std::regex_search(source, m, declaration)) return 0;
    return 1 + int(std::count(source.begin(), source.begin() + m.position(0) + m.length(0), '\n'));
}

}  // namespace fxport::xlate
