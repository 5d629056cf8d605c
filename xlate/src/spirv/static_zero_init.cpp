// See static_zero_init.h: file-scope statics without an initializer start at zero.
#include "spirv/static_zero_init.h"

#include <map>


namespace fxport::xlate {

namespace {

constexpr std::uint32_t kOpTypeBool = 20, kOpTypeMatrix = 24, kOpTypeArray = 28, kOpTypeStruct = 30,
                        kOpTypePointer = 32, kOpVariable = 59, kStoragePrivate = 6;
// Past this many components the zero-filled initializer SPIRV-Cross writes (every element
// spelled out) outweighs the value of the rule; such a big array is left as glslang declares it.
constexpr std::uint64_t kMaxComponents = 4096;

// The scalar components of `type`, 0 when it holds anything but numbers and bools (an object, a
// runtime array) or is too deep to judge.
std::uint64_t componentCount(const ParsedSpirv& m, std::uint32_t type, int depth = 0) {
    const SpirvInstruction* d = m.definition(type);
    if (!d || depth > 16) return 0;
    const auto& w = d->words;
    switch (d->opcode()) {
    case kOpTypeBool:
    case spv_op::TypeInt:
    case spv_op::TypeFloat: return 1;
    case spv_op::TypeVector:
    case kOpTypeMatrix: return w.size() == 4 ? w[3] * componentCount(m, w[2], depth + 1) : 0;
    case kOpTypeArray: {
        const SpirvInstruction* length = w.size() == 4 ? m.definition(w[3]) : nullptr;
        if (!length || length->opcode() != spv_op::Constant || length->words.size() != 4) return 0;
        return std::uint64_t(length->words[3]) * componentCount(m, w[2], depth + 1);
    }
    case kOpTypeStruct: {
        std::uint64_t sum = 0;
        for (size_t k = 2; k < w.size(); ++k) {
            std::uint64_t member = componentCount(m, w[k], depth + 1);
            if (!member) return 0;
            sum += member;
        }
        return sum;
    }
    default: return 0;
    }
}

}  // namespace

bool staticVariablesStartAtZero(ParsedSpirv& m) {
    bool changed = false;
    std::map<std::uint32_t, std::uint32_t> nullOf;  // pointee type -> its OpConstantNull, once emitted
    m.rewrite([&](const SpirvInstruction& inst, std::vector<SpirvInstruction>& out) {
        // OpVariable %pointer-type %id Private (no initializer operand)
        const auto& w = inst.words;
        if (inst.opcode() != kOpVariable || w.size() != 4 || w[3] != kStoragePrivate) return out.push_back(inst);
        const SpirvInstruction* pointer = m.definition(w[1]);
        if (!pointer || pointer->opcode() != kOpTypePointer || pointer->words.size() != 4) return out.push_back(inst);
        const std::uint32_t pointee = pointer->words[3];
        const std::uint64_t components = componentCount(m, pointee);
        if (components == 0 || components > kMaxComponents) return out.push_back(inst);
        auto known = nullOf.find(pointee);
        if (known == nullOf.end()) {  // emitted here, among the globals, so it precedes its use
            const std::uint32_t id = m.newId();
            out.push_back({{spirvFirstWord(spv_op::ConstantNull, 3), pointee, id}});
            known = nullOf.emplace(pointee, id).first;
        }
        out.push_back({{spirvFirstWord(kOpVariable, 5), w[1], w[2], w[3], known->second}});
        changed = true;
    });
    return changed;
}

}  // namespace fxport::xlate
