#include "spirv/spirv_fixups.h"

#include "spirv/spirv_integer_fixups.h"
#include "spirv/spirv_negated_comparisons.h"

#include <spirv-tools/libspirv.h>
#include <spirv-tools/optimizer.hpp>

#include <functional>
#include <map>
#include <set>

#include <string>

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kHeaderWords = 5;
constexpr std::uint32_t kOpTypeBool = 20;
constexpr std::uint32_t kOpCopyObject = 83;
constexpr std::uint32_t kOpAny = 154;
constexpr std::uint32_t kOpAll = 155;
constexpr std::uint32_t kOpUDiv = 134;
constexpr std::uint32_t kOpSDiv = 135;
constexpr std::uint32_t kOpFDiv = 136;
constexpr std::uint32_t kOpUMod = 137;
constexpr std::uint32_t kOpSRem = 138;
constexpr std::uint32_t kOpSMod = 139;
constexpr std::uint32_t kOpFRem = 140;
constexpr std::uint32_t kOpFMod = 141;

// HLSL's `%` and fmod() truncate like C (fxc: 42 % -5 == 2, -42 % 5 == -2, for floats and ints);
// glslang emits OpFMod / OpSMod for both, whose result takes the sign of the divisor (GLSL's
// mod(): 42 % -5 == -3). OpFRem / OpSRem are the truncating ones, with the same operands. HLSL has
// no floored remainder, so every OpFMod / OpSMod glslang emits is one of these.
// Test: conformance arithmetic-float / arithmetic-int, xlate.SpirvFixups.RemainderTruncates.
void remainderTruncates(std::vector<std::uint32_t>& words) {
    for (size_t at = kHeaderWords; at < words.size();) {
        std::uint32_t count = words[at] >> 16;
        if (count == 0) return;  // malformed: leave it to the validator downstream
        std::uint32_t op = words[at] & 0xFFFFu;
        if (op == kOpFMod) words[at] = (count << 16) | kOpFRem;
        if (op == kOpSMod) words[at] = (count << 16) | kOpSRem;
        at += count;
    }
}

// The result type of every value and the instructions by offset, from SPIRV-Tools' parser (which
// knows which opcodes have a result type), for fix-ups that depend on an operand's type.
struct ModuleTypes {
    std::map<std::uint32_t, std::uint32_t> typeOf;  // result id -> type id
    std::set<std::uint32_t> boolTypes;              // ids of OpTypeBool
    std::vector<size_t> anyAll;                     // offsets of OpAny / OpAll
};

bool readTypes(const std::vector<std::uint32_t>& words, ModuleTypes& out) {
    spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_0);
    struct Ctx {
        ModuleTypes* types;
        const std::uint32_t* base;
    } ctx{&out, words.data()};
    auto onInstruction = [](void* user, const spv_parsed_instruction_t* inst) -> spv_result_t {
        auto* c = static_cast<Ctx*>(user);
        if (inst->result_id && inst->type_id) c->types->typeOf[inst->result_id] = inst->type_id;
        if (inst->opcode == kOpTypeBool) c->types->boolTypes.insert(inst->result_id);
        if (inst->opcode == kOpAny || inst->opcode == kOpAll) c->types->anyAll.push_back(size_t(inst->words - c->base));
        return SPV_SUCCESS;
    };
    spv_result_t r = spvBinaryParse(context, &ctx, words.data(), words.size(), nullptr, onInstruction, nullptr);
    spvContextDestroy(context);
    return r == SPV_SUCCESS;
}

// HLSL's any()/all() take scalars too (any(x) is x != 0); glslang emits OpAny/OpAll on the scalar
// bool, which SPIR-V allows only on vectors, and SPIRV-Cross writes `any(bool)`, which the GL
// driver refuses at the first Apply(). Of a scalar, both are the scalar itself.
// Test: runtime HlslSemantics.BoolCastsAndAny.
void anyAllOfScalarIsTheScalar(std::vector<std::uint32_t>& words, const ModuleTypes& types) {
    for (size_t at : types.anyAll) {
        if (at + 3 >= words.size() || (words[at] >> 16) != 4) continue;
        auto operandType = types.typeOf.find(words[at + 3]);
        if (operandType != types.typeOf.end() && types.boolTypes.count(operandType->second))
            words[at] = (4u << 16) | kOpCopyObject;
    }
}

}  // namespace

namespace {

// Whether an instruction with one of `opcodes` occurs: a linear scan, so that the fix-ups and
// checks that parse or optimise the module cost nothing on shaders that cannot need them.
bool hasOpcode(const std::vector<std::uint32_t>& words, std::initializer_list<std::uint32_t> opcodes) {
    for (size_t at = kHeaderWords; at < words.size();) {
        std::uint32_t count = words[at] >> 16;
        if (count == 0) return false;
        for (std::uint32_t op : opcodes)
            if ((words[at] & 0xFFFFu) == op) return true;
        at += count;
    }
    return false;
}

}  // namespace

void applySpirvFixups(std::vector<std::uint32_t>& words) {
    if (words.size() < kHeaderWords) return;
    remainderTruncates(words);
    ModuleTypes types;
    if (hasOpcode(words, {kOpAny, kOpAll}) && readTypes(words, types)) anyAllOfScalarIsTheScalar(words, types);
    maskShiftCounts(words);
    floatToUnsignedSaturates(words);
    if (hasOpcode(words, {168})) negatedComparisonsAsOpposites(words);  // OpLogicalNot
}

namespace {

constexpr std::uint32_t kOpConstant = 43;
constexpr std::uint32_t kOpConstantComposite = 44;
constexpr std::uint32_t kOpConstantNull = 46;

bool forwardLocals(std::vector<std::uint32_t>& words) {
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_0);
    optimizer.SetMessageConsumer([](spv_message_level_t, const char*, const spv_position_t&, const char*) {});
    optimizer.RegisterPass(spvtools::CreateMergeReturnPass())
        .RegisterPass(spvtools::CreateInlineExhaustivePass())
        .RegisterPass(spvtools::CreateScalarReplacementPass())
        .RegisterPass(spvtools::CreateLocalAccessChainConvertPass())
        .RegisterPass(spvtools::CreateLocalSingleBlockLoadStoreElimPass())
        .RegisterPass(spvtools::CreateLocalSingleStoreElimPass());
    spvtools::OptimizerOptions options;
    options.set_run_validator(false);
    std::vector<std::uint32_t> out;
    if (!optimizer.Run(words.data(), words.size(), &out, options)) return false;
    words = std::move(out);
    return true;
}

}  // namespace

bool dividesByConstantZero(const std::vector<std::uint32_t>& original, bool floatsToo) {
    if (original.size() < kHeaderWords ||
        !hasOpcode(original, {kOpUDiv, kOpSDiv, kOpFDiv, kOpUMod, kOpSRem, kOpSMod, kOpFRem, kOpFMod}))  // no division at all
        return false;
    std::vector<std::uint32_t> words = original;
    if (!forwardLocals(words)) return false;
    // Constants that are zero (a scalar of value 0 or -0.0, a null, a composite with a zero part).
    std::set<std::uint32_t> zero;
    std::vector<std::pair<std::uint32_t, size_t>> divisions;  // (divisor id, offset)
    for (size_t at = kHeaderWords; at < words.size();) {
        std::uint32_t count = words[at] >> 16, op = words[at] & 0xFFFFu;
        if (count == 0 || at + count > words.size()) return false;
        if (op == kOpConstant && count == 4 && (words[at + 3] & 0x7FFFFFFFu) == 0) zero.insert(words[at + 2]);
        if (op == kOpConstantNull && count == 3) zero.insert(words[at + 2]);
        if (op == kOpConstantComposite)
            for (std::uint32_t k = 3; k < count; ++k)
                if (zero.count(words[at + k])) zero.insert(words[at + 2]);
        const bool integer = op == kOpUDiv || op == kOpSDiv || op == kOpUMod || op == kOpSRem || op == kOpSMod;
        const bool real = op == kOpFDiv || op == kOpFRem || op == kOpFMod;
        if ((integer || (real && floatsToo)) && count == 5) divisions.push_back({words[at + 4], at});
        at += count;
    }
    for (const auto& [divisor, at] : divisions)
        if (zero.count(divisor)) return true;
    return false;
}

namespace {

// Runs the passes `add` registers; false (with spirv-opt's errors) when it refuses the module.
bool runPasses(std::vector<std::uint32_t>& words, std::string* error,
               const std::function<void(spvtools::Optimizer&)>& add) {
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_0);
    std::string messages;
    optimizer.SetMessageConsumer([&](spv_message_level_t level, const char*, const spv_position_t&, const char* message) {
        if (level <= SPV_MSG_ERROR) messages += std::string(message) + "\n";
    });
    add(optimizer);
    spvtools::OptimizerOptions options;
    options.set_run_validator(false);  // spirvToGlsl's SPIRV-Cross parse is the check downstream
    std::vector<std::uint32_t> out;
    if (!optimizer.Run(words.data(), words.size(), &out, options)) {
        if (error) *error = messages.empty() ? "spirv-opt could not legalise the module" : messages;
        return false;
    }
    words = std::move(out);
    return true;
}

}  // namespace

bool legalizeSpirv(std::vector<std::uint32_t>& words, std::string* error) {
    // The order glslang uses for HLSL (its SpirvToolsTransform), so that the GLSL we emit is what it
    // was when glslang ran these passes itself. The two simplification passes fold constants; the
    // division fold that traps in spirv-opt (spirv_integer_fixups.h) runs before each of them, once
    // forwarding has made the operands constant.
    bool ok = runPasses(words, error, [](spvtools::Optimizer& o) {
        o.RegisterPass(spvtools::CreateWrapOpKillPass())
            .RegisterPass(spvtools::CreateDeadBranchElimPass())
            .RegisterPass(spvtools::CreateMergeReturnPass())
            .RegisterPass(spvtools::CreateInlineExhaustivePass())
            .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass())
            .RegisterPass(spvtools::CreateScalarReplacementPass())
            .RegisterPass(spvtools::CreateLocalAccessChainConvertPass())
            .RegisterPass(spvtools::CreateLocalSingleBlockLoadStoreElimPass())
            .RegisterPass(spvtools::CreateLocalSingleStoreElimPass());
    });
    if (!ok) return false;
    foldIntMinByMinusOne(words);
    ok = runPasses(words, error, [](spvtools::Optimizer& o) {
        o.RegisterPass(spvtools::CreateSimplificationPass())
            .RegisterPass(spvtools::CreateAggressiveDCEPass())
            .RegisterPass(spvtools::CreateVectorDCEPass())
            .RegisterPass(spvtools::CreateDeadInsertElimPass())
            .RegisterPass(spvtools::CreateAggressiveDCEPass())
            .RegisterPass(spvtools::CreateDeadBranchElimPass())
            .RegisterPass(spvtools::CreateBlockMergePass())
            .RegisterPass(spvtools::CreateLocalMultiStoreElimPass())
            .RegisterPass(spvtools::CreateIfConversionPass());
    });
    if (!ok) return false;
    foldIntMinByMinusOne(words);
    return runPasses(words, error, [](spvtools::Optimizer& o) {
        o.RegisterPass(spvtools::CreateSimplificationPass())
            .RegisterPass(spvtools::CreateAggressiveDCEPass())
            .RegisterPass(spvtools::CreateVectorDCEPass())
            .RegisterPass(spvtools::CreateDeadInsertElimPass())
            .RegisterPass(spvtools::CreateInterpolateFixupPass())
            .RegisterPass(spvtools::CreateAggressiveDCEPass())
            .RegisterPass(spvtools::CreateCFGCleanupPass());
    });
}

}  // namespace fxport::xlate
