// See parsed_spirv.h: a SPIR-V module as an editable list of instructions.
#include "spirv/parsed_spirv.h"

#include <spirv-tools/libspirv.h>

#include <cstring>

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kHeaderWords = 5;

bool isIdOperand(spv_operand_type_t t) {
    return t == SPV_OPERAND_TYPE_ID || t == SPV_OPERAND_TYPE_MEMORY_SEMANTICS_ID || t == SPV_OPERAND_TYPE_SCOPE_ID;
}

}  // namespace

std::string spirvLiteralString(const SpirvInstruction& in, size_t first) {
    std::string s;
    for (size_t k = first; k < in.words.size(); ++k)
        for (int b = 0; b < 4; ++b) {
            const char c = char((in.words[k] >> (8 * b)) & 0xFFu);
            if (c == 0) return s;
            s += c;
        }
    return s;
}

std::vector<std::uint32_t> spirvLiteralWords(const std::string& s) {
    std::vector<std::uint32_t> words((s.size() + 4) / 4, 0);
    for (size_t k = 0; k < s.size(); ++k) words[k / 4] |= std::uint32_t(static_cast<unsigned char>(s[k])) << (8 * (k % 4));
    return words;
}

bool ParsedSpirv::parse(const std::vector<std::uint32_t>& words) {
    if (words.size() < kHeaderWords) return false;
    *this = ParsedSpirv();
    header_.assign(words.begin(), words.begin() + kHeaderWords);
    spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_0);
    auto onInstruction = [](void* user, const spv_parsed_instruction_t* inst) -> spv_result_t {
        auto* self = static_cast<ParsedSpirv*>(user);
        self->instructions.push_back({std::vector<std::uint32_t>(inst->words, inst->words + inst->num_words)});
        SpirvInstructionIds ids;
        ids.type = inst->type_id;
        ids.result = inst->result_id;
        for (std::uint16_t k = 0; k < inst->num_operands; ++k)
            if (isIdOperand(inst->operands[k].type)) ids.operands.push_back(inst->operands[k].offset);
        self->ids_.push_back(std::move(ids));
        if (inst->result_id && inst->type_id) self->typeOf_[inst->result_id] = inst->type_id;
        return SPV_SUCCESS;
    };
    spv_result_t r = spvBinaryParse(context, this, words.data(), words.size(), nullptr, onInstruction, nullptr);
    spvContextDestroy(context);
    if (r != SPV_SUCCESS) return false;
    index();
    return true;
}

bool ParsedSpirv::reparse() {
    ParsedSpirv fresh;
    if (!fresh.parse(assemble())) return false;
    *this = std::move(fresh);
    return true;
}

const SpirvInstructionIds& ParsedSpirv::ids(size_t index) const {
    static const SpirvInstructionIds kNone;
    return index < ids_.size() ? ids_[index] : kNone;
}

// Where the values (result id in word 2, after its type) and the types (OpTypeVoid 19 ...
// OpTypeForwardPointer 39, result id in word 1) are defined.
void ParsedSpirv::index() {
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
std::vector<std::uint32_t> ParsedSpirv::assemble() const {
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

bool ParsedSpirv::has(std::initializer_list<std::uint32_t> opcodes) const {
    for (const auto& inst : instructions)
        for (std::uint32_t op : opcodes)
            if (inst.opcode() == op) return true;
    return false;
}

size_t ParsedSpirv::firstFunction() const {
    for (size_t i = 0; i < instructions.size(); ++i)
        if (instructions[i].opcode() == spv_op::Function) return i;
    return instructions.size();
}

std::uint32_t ParsedSpirv::typeOf(std::uint32_t id) const {
    auto it = typeOf_.find(id);
    return it == typeOf_.end() ? 0 : it->second;
}

const SpirvInstruction* ParsedSpirv::definition(std::uint32_t id) const {
    auto it = definedAt_.find(id);
    return it == definedAt_.end() ? nullptr : &instructions[it->second];
}

std::pair<std::uint32_t, std::uint32_t> ParsedSpirv::components(std::uint32_t type) const {
    const SpirvInstruction* t = definition(type);
    if (t && t->opcode() == spv_op::TypeVector && t->words.size() == 4) return {t->words[2], t->words[3]};
    return {type, 1};
}

std::uint32_t ParsedSpirv::addGlobal(std::vector<std::uint32_t> words) {
    std::uint32_t id = newId();
    words[2] = id;
    typeOf_[id] = words[1];
    globals_.push_back({std::move(words)});
    return id;
}

std::uint32_t ParsedSpirv::addType(std::vector<std::uint32_t> words) {
    words[1] = newId();
    globals_.push_back({words});
    types_.push_back({words});
    return words[1];
}

std::uint32_t ParsedSpirv::findType(const std::function<bool(const SpirvInstruction&)>& match) const {
    for (const auto* list : {&instructions, &types_})
        for (const auto& inst : *list)
            if (match(inst)) return inst.words[1];
    return 0;
}

std::uint32_t ParsedSpirv::vectorLike(std::uint32_t scalar, std::uint32_t type) {
    const std::uint32_t count = components(type).second;
    if (count == 1) return scalar;
    std::uint32_t vector = findType([&](const SpirvInstruction& i) {
        return i.opcode() == spv_op::TypeVector && i.words.size() == 4 && i.words[2] == scalar && i.words[3] == count;
    });
    if (!vector) vector = addType({spirvFirstWord(spv_op::TypeVector, 4), 0, scalar, count});
    return vector;
}

std::uint32_t ParsedSpirv::floatTypeLike(std::uint32_t type) {
    std::uint32_t scalar = findType([](const SpirvInstruction& i) { return i.opcode() == spv_op::TypeFloat && i.words.size() == 3 && i.words[2] == 32; });
    if (!scalar) scalar = addType({spirvFirstWord(spv_op::TypeFloat, 3), 0, 32});
    return vectorLike(scalar, type);
}

std::uint32_t ParsedSpirv::boolTypeLike(std::uint32_t type) {
    std::uint32_t scalar = findType([](const SpirvInstruction& i) { return i.opcode() == spv_op::TypeBool; });
    if (!scalar) scalar = addType({spirvFirstWord(spv_op::TypeBool, 2), 0});
    return vectorLike(scalar, type);
}

std::uint32_t ParsedSpirv::intType() {
    std::uint32_t t = findType([](const SpirvInstruction& i) { return i.opcode() == spv_op::TypeInt && i.words.size() == 4 && i.words[2] == 32 && i.words[3] == 1; });
    return t ? t : addType({spirvFirstWord(spv_op::TypeInt, 4), 0, 32, 1});
}

std::uint32_t ParsedSpirv::uintType() {
    std::uint32_t t = findType([](const SpirvInstruction& i) { return i.opcode() == spv_op::TypeInt && i.words.size() == 4 && i.words[2] == 32 && i.words[3] == 0; });
    return t ? t : addType({spirvFirstWord(spv_op::TypeInt, 4), 0, 32, 0});
}

std::uint32_t ParsedSpirv::constant(std::uint32_t scalarType, std::uint32_t value) {
    auto key = std::make_tuple(scalarType, value);
    if (auto it = constants_.find(key); it != constants_.end()) return it->second;
    return constants_[key] = addGlobal({spirvFirstWord(spv_op::Constant, 4), scalarType, 0, value});
}

std::uint32_t ParsedSpirv::composite(std::uint32_t type, const std::vector<std::uint32_t>& parts) {
    std::vector<std::uint32_t> words{spirvFirstWord(spv_op::ConstantComposite, 3 + parts.size()), type, 0};
    words.insert(words.end(), parts.begin(), parts.end());
    return addGlobal(std::move(words));
}

std::uint32_t ParsedSpirv::splatConstant(std::uint32_t type, std::uint32_t value) {
    auto key = std::make_tuple(type, value);
    if (auto it = splats_.find(key); it != splats_.end()) return it->second;
    std::uint32_t id = 0;
    auto [component, count] = components(type);
    if (value == 0) id = addGlobal({spirvFirstWord(spv_op::ConstantNull, 3), type, 0});
    else if (count == 1) id = constant(component, value);
    else id = composite(type, std::vector<std::uint32_t>(count, constant(component, value)));
    return splats_[key] = id;
}

std::uint32_t ParsedSpirv::glslStd450() {
    if (glslStd450_) return glslStd450_;
    static const char kName[] = "GLSL.std.450";  // 12 characters and the terminating zero: 4 words
    for (const auto& inst : instructions)
        if (inst.opcode() == spv_op::ExtInstImport && inst.words.size() == 6 &&
            std::memcmp(inst.words.data() + 2, kName, sizeof kName) == 0)
            return glslStd450_ = inst.words[1];
    import_.words.assign(6, 0);
    import_.words[0] = spirvFirstWord(spv_op::ExtInstImport, 6);
    import_.words[1] = glslStd450_ = newId();
    std::memcpy(import_.words.data() + 2, kName, sizeof kName);
    return glslStd450_;
}

SpirvInstruction ParsedSpirv::value(std::uint32_t opcode, std::uint32_t type, const std::vector<std::uint32_t>& operands) {
    std::uint32_t id = newId();
    typeOf_[id] = type;
    std::vector<std::uint32_t> words{spirvFirstWord(opcode, 3 + operands.size()), type, id};
    words.insert(words.end(), operands.begin(), operands.end());
    return {std::move(words)};
}

void ParsedSpirv::rewrite(const std::function<void(const SpirvInstruction&, std::vector<SpirvInstruction>&)>& visit) {
    std::vector<SpirvInstruction> out;
    out.reserve(instructions.size());
    const std::vector<SpirvInstruction> before = instructions;
    for (const auto& inst : before) visit(inst, out);
    instructions = std::move(out);
    ids_.clear();
    index();
}

bool runSpirvPasses(ParsedSpirv& m, const std::vector<SpirvPass>& passes) {
    bool changed = false;
    for (const SpirvPass& pass : passes) {
        if (!pass || !pass(m)) continue;
        changed = true;
        if (!m.reparse()) break;
    }
    return changed;
}

void runSpirvPasses(std::vector<std::uint32_t>& words, const std::vector<SpirvPass>& passes) {
    ParsedSpirv m;
    if (m.parse(words) && runSpirvPasses(m, passes)) words = m.assemble();
}

std::optional<std::vector<std::uint32_t>> spirvConstantComponents(const ParsedSpirv& m, std::uint32_t id) {
    const SpirvInstruction* d = m.definition(id);
    if (!d) return std::nullopt;
    if (d->opcode() == spv_op::Constant && d->words.size() == 4) return std::vector<std::uint32_t>{d->words[3]};
    if (d->opcode() == spv_op::ConstantNull) return std::vector<std::uint32_t>(m.components(d->words[1]).second, 0u);
    if (d->opcode() != spv_op::ConstantComposite) return std::nullopt;
    std::vector<std::uint32_t> out;
    for (size_t k = 3; k < d->words.size(); ++k) {
        auto part = spirvConstantComponents(m, d->words[k]);
        if (!part || part->size() != 1) return std::nullopt;
        out.push_back(part->front());
    }
    return out;
}

}  // namespace fxport::xlate
