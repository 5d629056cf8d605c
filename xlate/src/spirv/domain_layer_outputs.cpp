#include "spirv/domain_layer_outputs.h"

#include <map>
#include <string>

#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kEntryPoint = 15, kVariable = 59, kStore = 62, kDecorate = 71, kDecorateString = 5632;
constexpr std::uint32_t kTessellationEvaluation = 2, kOutput = 3, kBuiltIn = 11, kUserSemantic = 5635;
constexpr std::uint32_t kLayer = 9, kViewportIndex = 10;

// Output variables with the two semantics -> the built-in each stands for.
std::map<std::uint32_t, std::uint32_t> layerOutputs(const ParsedSpirv& m) {
    std::map<std::uint32_t, std::uint32_t> bySemantic, outputs;
    for (const SpirvInstruction& in : m.instructions) {
        if (in.opcode() == kEntryPoint && in.word(1) != kTessellationEvaluation) return {};
        if (in.opcode() != kDecorateString || in.word(2) != kUserSemantic) continue;
        const std::string semantic = toUpper(spirvLiteralString(in, 3));
        if (semantic == "SV_RENDERTARGETARRAYINDEX") bySemantic[in.word(1)] = kLayer;
        if (semantic == "SV_VIEWPORTARRAYINDEX") bySemantic[in.word(1)] = kViewportIndex;
    }
    for (const SpirvInstruction& in : m.instructions)
        if (in.opcode() == kVariable && in.word(3) == kOutput && bySemantic.count(in.word(2))) outputs[in.word(2)] = bySemantic[in.word(2)];
    return outputs;
}

}  // namespace

bool domainLayerOutputs(ParsedSpirv& m) {
    const std::map<std::uint32_t, std::uint32_t> outputs = layerOutputs(m);
    if (outputs.empty()) return false;
    std::map<std::uint32_t, std::uint32_t> twin;
    for (const auto& [variable, builtIn] : outputs) twin[variable] = m.newId();
    m.rewrite([&](const SpirvInstruction& in, std::vector<SpirvInstruction>& out) {
        out.push_back(in);
        const std::uint32_t op = in.opcode();
        if (op == kEntryPoint) {
            for (const auto& [variable, id] : twin) out.back().words.push_back(id);
            out.back().words[0] = spirvFirstWord(kEntryPoint, out.back().words.size());
        } else if (op == kVariable && twin.count(in.word(2))) {
            out.push_back({{spirvFirstWord(kVariable, 4), in.word(1), twin.at(in.word(2)), kOutput}});
        } else if (op == kStore && twin.count(in.word(1))) {
            out.push_back({{spirvFirstWord(kStore, 3), twin.at(in.word(1)), in.word(2)}});
        } else if (op == kDecorateString && in.word(2) == kUserSemantic && twin.count(in.word(1))) {
            out.push_back({{spirvFirstWord(kDecorate, 4), twin.at(in.word(1)), kBuiltIn, outputs.at(in.word(1))}});
        }
    });
    return true;
}

}  // namespace fxport::xlate
