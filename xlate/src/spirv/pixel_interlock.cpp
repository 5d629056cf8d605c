// See pixel_interlock.h.
#include "spirv/pixel_interlock.h"

#include <algorithm>
#include <set>

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kName = 5, kExtension = 10, kCapability = 17, kEntryPoint = 15, kExecutionMode = 16, kFunction = 54,
                        kFunctionEnd = 56, kVariable = 59, kLabel = 248, kReturn = 253, kReturnValue = 254;
constexpr std::uint32_t kBeginInterlock = 5364, kEndInterlock = 5365, kPixelInterlockOrdered = 5366,
                        kFragmentShaderPixelInterlock = 5378, kFragment = 4;

SpirvInstruction instruction(std::uint32_t opcode, std::vector<std::uint32_t> operands) {
    SpirvInstruction in;
    in.words.push_back(spirvFirstWord(opcode, operands.size() + 1));
    in.words.insert(in.words.end(), operands.begin(), operands.end());
    return in;
}

}  // namespace

bool pixelInterlockForOrderedViews(ParsedSpirv& m, const std::vector<std::string>& views) {
    if (views.empty()) return false;
    std::uint32_t entry = 0;
    std::set<std::uint32_t> named, variables;
    for (const SpirvInstruction& in : m.instructions) {
        if (in.opcode() == kEntryPoint) {
            if (in.word(1) != kFragment) return false;
            entry = in.word(2);
        }
        if (in.opcode() == kName && std::find(views.begin(), views.end(), spirvLiteralString(in, 2)) != views.end()) named.insert(in.word(1));
        if (in.opcode() == kVariable) variables.insert(in.word(2));
    }
    if (!entry || std::none_of(named.begin(), named.end(), [&](std::uint32_t id) { return variables.count(id) > 0; })) return false;
    bool inEntry = false, begun = false, capabilityDone = false, extensionDone = false, modeDone = false;
    m.rewrite([&](const SpirvInstruction& in, std::vector<SpirvInstruction>& out) {
        const std::uint32_t op = in.opcode();
        // Module-level declarations, each in its section: capability first, the extension before
        // the imports, the execution mode beside the others.
        if (!capabilityDone) {
            out.push_back(instruction(kCapability, {kFragmentShaderPixelInterlock}));
            capabilityDone = true;
        }
        if (!extensionDone && op != kCapability) {
            std::vector<std::uint32_t> name = spirvLiteralWords("SPV_EXT_fragment_shader_interlock");
            out.push_back(instruction(kExtension, name));
            extensionDone = true;
        }
        if (!modeDone && op == kExecutionMode) {
            out.push_back(instruction(kExecutionMode, {entry, kPixelInterlockOrdered}));
            modeDone = true;
        }
        if (inEntry && !begun && op != kVariable && op != kLabel) {
            out.push_back(instruction(kBeginInterlock, {}));
            begun = true;
        }
        if (inEntry && (op == kReturn || op == kReturnValue)) out.push_back(instruction(kEndInterlock, {}));
        if (op == kFunction) inEntry = in.word(2) == entry;
        if (op == kFunctionEnd) inEntry = false;
        out.push_back(in);
    });
    return begun;
}

}  // namespace fxport::xlate
