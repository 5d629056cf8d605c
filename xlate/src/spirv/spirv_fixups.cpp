#include "spirv/spirv_fixups.h"

#include "spirv/spirv_integer_fixups.h"
#include "spirv/parsed_spirv.h"
#include "spirv/spirv_negated_comparisons.h"
#include "spirv/reversed_bounds.h"

#include <spirv-tools/optimizer.hpp>

#include <functional>
#include <set>
#include <string>

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kHeaderWords = 5;
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
bool remainderTruncates(ParsedSpirv& m) {
    bool changed = false;
    for (SpirvInstruction& inst : m.instructions) {
        const std::uint32_t count = std::uint32_t(inst.words.size());
        if (inst.opcode() == spv_op::FMod) inst.words[0] = spirvFirstWord(spv_op::FRem, count);
        else if (inst.opcode() == spv_op::SMod) inst.words[0] = spirvFirstWord(spv_op::SRem, count);
        else continue;
        changed = true;
    }
    return changed;
}

// HLSL's any()/all() take scalars too (any(x) is x != 0); glslang emits OpAny/OpAll on the scalar
// bool, which SPIR-V allows only on vectors, and SPIRV-Cross writes `any(bool)`, which the GL
// driver refuses at the first Apply(). Of a scalar, both are the scalar itself.
// Test: runtime HlslSemantics.BoolCastsAndAny.
bool anyAllOfScalarIsTheScalar(ParsedSpirv& m) {
    bool changed = false;
    for (SpirvInstruction& inst : m.instructions) {
        if ((inst.opcode() != spv_op::Any && inst.opcode() != spv_op::All) || inst.words.size() != 4) continue;
        const SpirvInstruction* operandType = m.definition(m.typeOf(inst.words[3]));
        if (!operandType || operandType->opcode() != spv_op::TypeBool) continue;
        inst.words[0] = spirvFirstWord(spv_op::CopyObject, 4);
        changed = true;
    }
    return changed;
}

// HLSL's EvaluateAttributeAtSample takes a uint sample index, and glslang passes it on as a uint
// to GLSL.std.450 InterpolateAtSample; SPIRV-Cross then writes interpolateAtSample(x, uint), which
// GLSL does not have (its index is an int) and the GL driver refuses. The index is bitcast to int.
// Test: conformance eval-attrib, xlate PerSampleInputs.EvaluateAttributeIntrinsicsReachTheInput.
bool interpolateAtSampleTakesInt(ParsedSpirv& m) {
    constexpr std::uint32_t kInterpolateAtSample = 77, kOpBitcast = 124;
    if (!m.has({spv_op::ExtInst})) return false;
    const std::uint32_t std450 = m.glslStd450();
    bool changed = false;
    m.rewrite([&](const SpirvInstruction& in, std::vector<SpirvInstruction>& out) {
        // %r = OpExtInst %type %std450 InterpolateAtSample %interpolant %sample
        const auto& w = in.words;
        if (in.opcode() != spv_op::ExtInst || w.size() != 7 || w[3] != std450 || w[4] != kInterpolateAtSample) return out.push_back(in);
        const SpirvInstruction* type = m.definition(m.typeOf(w[6]));
        if (!type || type->opcode() != spv_op::TypeInt || type->word(3) != 0) return out.push_back(in);
        SpirvInstruction index = m.value(kOpBitcast, m.intType(), {w[6]});
        SpirvInstruction call = in;
        call.words[6] = index.words[2];
        out.push_back(std::move(index));
        out.push_back(std::move(call));
        changed = true;
    });
    return changed;
}

// Whether an instruction with one of `opcodes` occurs: a linear scan, so that the checks that
// optimise the module cost nothing on shaders that cannot need them.
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

bool applySpirvFixups(ParsedSpirv& m) {
    return runSpirvPasses(m, {remainderTruncates, anyAllOfScalarIsTheScalar, maskShiftCounts, floatToUnsignedSaturates,
                           negatedComparisonsAsOpposites, interpolateAtSampleTakesInt, smoothstepAsFxcArithmetic, clampAsMinOfMax});
}

namespace {

constexpr std::uint32_t kOpConstant = 43;
constexpr std::uint32_t kOpConstantComposite = 44;
constexpr std::uint32_t kOpConstantNull = 46;

bool forwardLocals(std::vector<std::uint32_t>& words) {
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_0);
    optimizer.SetMessageConsumer([](spv_message_level_t, const char*, const spv_position_t&, const char*) {});
    // A file-scope static read by one function (after inlining, the entry point) becomes that
    // function's local, so that its value -- its initializer, zero when it has none
    // (static_zero_init.h) -- is forwarded like a local's: `static uint i; 1 / i` divides by zero.
    optimizer.RegisterPass(spvtools::CreateMergeReturnPass())
        .RegisterPass(spvtools::CreateInlineExhaustivePass())
        .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass())
        .RegisterPass(spvtools::CreatePrivateToLocalPass())
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

bool legalizeSpirv(std::vector<std::uint32_t>& words, std::string* error, bool sm2or3) {
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
    runSpirvPasses(words, {sm2or3 ? SpirvPass(intMinByMinusOneInFloats) : nullptr, foldIntMinByMinusOne,
                           sm2or3 ? SpirvPass(integerCastsOfFloatIntegers) : nullptr, sm2or3 ? SpirvPass(integerCastsOfFloatIntegers) : nullptr});
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
    runSpirvPasses(words, {sm2or3 ? SpirvPass(intMinByMinusOneInFloats) : nullptr, foldIntMinByMinusOne,
                           sm2or3 ? SpirvPass(integerCastsOfFloatIntegers) : nullptr, sm2or3 ? SpirvPass(integerCastsOfFloatIntegers) : nullptr});
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

bool forwardResourceCopies(std::vector<std::uint32_t>& words, std::string* error) {
    // Scalar replacement ran before constant folding made indices like `(int)co.x + (int)co.y`
    // constant; with them constant now, the array splits and the stores forward.
    return runPasses(words, error, [](spvtools::Optimizer& o) {
        o.RegisterPass(spvtools::CreateScalarReplacementPass())
            .RegisterPass(spvtools::CreateLocalAccessChainConvertPass())
            .RegisterPass(spvtools::CreateLocalSingleBlockLoadStoreElimPass())
            .RegisterPass(spvtools::CreateLocalSingleStoreElimPass())
            .RegisterPass(spvtools::CreateLocalMultiStoreElimPass())
            .RegisterPass(spvtools::CreateSimplificationPass())
            .RegisterPass(spvtools::CreateAggressiveDCEPass());
    });
}

}  // namespace fxport::xlate
