// See spirv_module_edit.h: a SPIR-V module as an editable list of instructions.
#include "spirv/spirv_module_edit.h"

#include <spirv-tools/libspirv.h>

#include <cstring>

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kHeaderWords = 5;

std::uint32_t firstWord(std::uint32_t opcode, size_t count) { return (std::uint32_t(count) << 16) | opcode; }

}  // namespace

bool SpirvModuleEdit::parse(const std::vector<std::uint32_t>& words) {
    if (words.size() < kHeaderWords) return false;
    header_.assign(words.begin(), words.begin() + kHeaderWords);
    instructions.clear();
    typeOf_.clear();
    spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_0);
    auto onInstruction = [](void* user, const spv_parsed_instruction_t* inst) -> spv_result_t {
        auto* self = static_cast<SpirvModuleEdit*>(user);
        self->instructions.push_back({std::vector<std::uint32_t>(inst->words, inst->words + inst->num_words)});
        if (inst->result_id && inst->type_id) self->typeOf_[inst->result_id] = inst->type_id;
        return SPV_SUCCESS;
    };
    spv_result_t r = spvBinaryParse(context, this, words.data(), words.size(), nullptr, onInstruction, nullptr);
    spvContextDestroy(context);
    if (r != SPV_SUCCESS) return false;
    index();
    return true;
}

// Where the values (result id in word 2, after its type) and the types (OpTypeVoid 19 ...
// OpTypeForwardPointer 39, result id in word 1) are defined.
void SpirvModuleEdit::index() {
    definedAt_.clear();
    for (size_t i = 0; i < instructions.size(); ++i) {
        const auto& w = instructions[i].words;
        const std::uint32_t op = instructions[i].opcode();
        // Types first: OpTypeInt's width (32) may also be the id of a value of that very type.
        if (op >= 19 && op <= 39 && w.size() > 1) definedAt_[w[1]] = i;
        else if (w.size() > 2 && typeOf_.count(w[2]) && typeOf_.at(w[2]) == w[1]) definedAt_[w[2]] = i;
    }
}

// New constants go before the first function (after every type they use); a new import before
// OpMemoryModel, where the layout rules of SPIR-V want imports.
std::vector<std::uint32_t> SpirvModuleEdit::assemble() const {
    std::vector<std::uint32_t> out = header_;
    auto append = [&](const SpirvInstruction& inst) { out.insert(out.end(), inst.words.begin(), inst.words.end()); };
    bool globalsDone = false;
    for (const auto& inst : instructions) {
        if (inst.opcode() == spv_op::MemoryModel && !import_.words.empty()) append(import_);
        if (inst.opcode() == spv_op::Function && !globalsDone) {
            for (const auto& g : globals_) append(g);
            globalsDone = true;
        }
        append(inst);
    }
    return out;
}

std::uint32_t SpirvModuleEdit::typeOf(std::uint32_t id) const {
    auto it = typeOf_.find(id);
    return it == typeOf_.end() ? 0 : it->second;
}

const SpirvInstruction* SpirvModuleEdit::definition(std::uint32_t id) const {
    auto it = definedAt_.find(id);
    return it == definedAt_.end() ? nullptr : &instructions[it->second];
}

std::pair<std::uint32_t, std::uint32_t> SpirvModuleEdit::components(std::uint32_t type) const {
    const SpirvInstruction* t = definition(type);
    if (t && t->opcode() == spv_op::TypeVector && t->words.size() == 4) return {t->words[2], t->words[3]};
    return {type, 1};
}

std::uint32_t SpirvModuleEdit::addGlobal(std::vector<std::uint32_t> words) {
    std::uint32_t id = newId();
    words[2] = id;
    typeOf_[id] = words[1];
    globals_.push_back({std::move(words)});
    return id;
}

std::uint32_t SpirvModuleEdit::addType(std::vector<std::uint32_t> words) {
    words[1] = newId();
    globals_.push_back({words});
    types_.push_back({words});
    return words[1];
}

std::uint32_t SpirvModuleEdit::floatTypeLike(std::uint32_t type) {
    const std::uint32_t count = components(type).second;
    auto find = [&](auto match) -> std::uint32_t {
        for (const auto* list : {&instructions, &types_})
            for (const auto& inst : *list)
                if (match(inst)) return inst.words[1];
        return 0;
    };
    std::uint32_t scalar = find([](const SpirvInstruction& i) { return i.opcode() == spv_op::TypeFloat && i.words.size() == 3 && i.words[2] == 32; });
    if (!scalar) scalar = addType({firstWord(spv_op::TypeFloat, 3), 0, 32});
    if (count == 1) return scalar;
    std::uint32_t vector = find([&](const SpirvInstruction& i) {
        return i.opcode() == spv_op::TypeVector && i.words.size() == 4 && i.words[2] == scalar && i.words[3] == count;
    });
    if (!vector) vector = addType({firstWord(spv_op::TypeVector, 4), 0, scalar, count});
    return vector;
}

std::uint32_t SpirvModuleEdit::constant(std::uint32_t scalarType, std::uint32_t value) {
    auto key = std::make_tuple(scalarType, value);
    if (auto it = constants_.find(key); it != constants_.end()) return it->second;
    return constants_[key] = addGlobal({firstWord(spv_op::Constant, 4), scalarType, 0, value});
}

std::uint32_t SpirvModuleEdit::composite(std::uint32_t type, const std::vector<std::uint32_t>& parts) {
    std::vector<std::uint32_t> words{firstWord(spv_op::ConstantComposite, 3 + parts.size()), type, 0};
    words.insert(words.end(), parts.begin(), parts.end());
    return addGlobal(std::move(words));
}

std::uint32_t SpirvModuleEdit::splatConstant(std::uint32_t type, std::uint32_t value) {
    auto key = std::make_tuple(type, value);
    if (auto it = splats_.find(key); it != splats_.end()) return it->second;
    std::uint32_t id = 0;
    auto [component, count] = components(type);
    if (value == 0) id = addGlobal({firstWord(spv_op::ConstantNull, 3), type, 0});
    else if (count == 1) id = constant(component, value);
    else id = composite(type, std::vector<std::uint32_t>(count, constant(component, value)));
    return splats_[key] = id;
}

std::uint32_t SpirvModuleEdit::glslStd450() {
    if (glslStd450_) return glslStd450_;
    static const char kName[] = "GLSL.std.450";  // 12 characters and the terminating zero: 4 words
    for (const auto& inst : instructions)
        if (inst.opcode() == spv_op::ExtInstImport && inst.words.size() == 6 &&
            std::memcmp(inst.words.data() + 2, kName, sizeof kName) == 0)
            return glslStd450_ = inst.words[1];
    import_.words.assign(6, 0);
    import_.words[0] = firstWord(spv_op::ExtInstImport, 6);
    import_.words[1] = glslStd450_ = newId();
    std::memcpy(import_.words.data() + 2, kName, sizeof kName);
    return glslStd450_;
}

SpirvInstruction SpirvModuleEdit::value(std::uint32_t opcode, std::uint32_t type, const std::vector<std::uint32_t>& operands) {
    std::uint32_t id = newId();
    typeOf_[id] = type;
    std::vector<std::uint32_t> words{firstWord(opcode, 3 + operands.size()), type, id};
    words.insert(words.end(), operands.begin(), operands.end());
    return {std::move(words)};
}

void SpirvModuleEdit::rewrite(const std::function<void(const SpirvInstruction&, std::vector<SpirvInstruction>&)>& visit) {
    std::vector<SpirvInstruction> out;
    out.reserve(instructions.size());
    const std::vector<SpirvInstruction> before = instructions;
    for (const auto& inst : before) visit(inst, out);
    instructions = std::move(out);
    index();
}

}  // namespace fxport::xlate
