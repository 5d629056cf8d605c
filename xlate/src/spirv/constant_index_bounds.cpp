// Constant array indices past the end in a legalised module (constant_index_bounds.h).
#include "spirv/constant_index_bounds.h"

#include <algorithm>
#include <map>

#include <spirv_cross/spirv.hpp>

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

std::optional<IndexPastEnd> constantIndexPastArrayEnd(const std::vector<std::uint32_t>& words) {
    ParsedSpirv m;
    if (!m.parse(words)) return std::nullopt;
    std::map<std::uint32_t, const SpirvInstruction*> types;
    std::map<std::uint32_t, std::int64_t> constants;  // 32-bit integer constants, sign-extended where signed
    std::map<std::uint32_t, bool> signedInt;
    for (const SpirvInstruction& in : m.instructions) {
        const std::uint32_t op = in.opcode();
        if (op == spv::OpTypeInt) signedInt[in.word(1)] = in.word(3) == 1;
        if (op == spv::OpTypeArray || op == spv::OpTypeStruct || op == spv::OpTypePointer || op == spv::OpTypeVector ||
            op == spv::OpTypeMatrix)
            types[in.word(1)] = &in;
        if (op == spv::OpConstant && in.words.size() == 4 && signedInt.count(in.word(1)))
            constants[in.word(2)] = signedInt[in.word(1)] ? std::int64_t(std::int32_t(in.word(3))) : std::int64_t(in.word(3));
    }
    for (const SpirvInstruction& in : m.instructions) {
        if (in.opcode() != spv::OpAccessChain && in.opcode() != spv::OpInBoundsAccessChain) continue;
        const SpirvInstruction* def = m.definition(in.word(3));
        auto pointer = types.find(def ? def->word(1) : 0);
        if (pointer == types.end() || pointer->second->opcode() != spv::OpTypePointer) continue;
        std::uint32_t type = pointer->second->word(3);
        for (size_t k = 4; k < in.words.size(); ++k) {
            auto t = types.find(type);
            if (t == types.end()) break;  // a scalar, or a runtime array (no length to pass)
            const SpirvInstruction& ty = *t->second;
            auto index = constants.find(in.words[k]);
            if (ty.opcode() == spv::OpTypeArray) {
                auto length = constants.find(ty.word(3));
                if (index != constants.end() && length != constants.end() && (index->second < 0 || index->second >= length->second))
                    return IndexPastEnd{index->second, length->second};
                type = ty.word(2);
            } else if (ty.opcode() == spv::OpTypeStruct) {
                if (index == constants.end() || index->second < 0 || size_t(index->second) + 2 >= ty.words.size()) break;
                type = ty.word(2 + size_t(index->second));
            } else if (ty.opcode() == spv::OpTypeVector || ty.opcode() == spv::OpTypeMatrix) {
                type = ty.word(2);
            } else {
                break;
            }
        }
    }
    return std::nullopt;
}

int deferredIndexLine(const std::string& source, std::int64_t index) {
    const size_t at = source.find("fxport_index(" + std::to_string(index) + ")");
    if (at == std::string::npos) return 0;
    return 1 + int(std::count(source.begin(), source.begin() + std::ptrdiff_t(at), '\n'));
}

}  // namespace fxport::xlate
