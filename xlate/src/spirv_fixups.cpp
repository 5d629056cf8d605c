#include "spirv_fixups.h"

#include <spirv-tools/optimizer.hpp>

#include <string>

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kHeaderWords = 5;
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

}  // namespace

void applySpirvFixups(std::vector<std::uint32_t>& words) {
    if (words.size() < kHeaderWords) return;
    remainderTruncates(words);
}

bool legalizeSpirv(std::vector<std::uint32_t>& words, std::string* error) {
    spvtools::Optimizer optimizer(SPV_ENV_VULKAN_1_0);
    std::string messages;
    optimizer.SetMessageConsumer([&](spv_message_level_t level, const char*, const spv_position_t&, const char* message) {
        if (level <= SPV_MSG_ERROR) messages += std::string(message) + "\n";
    });
    // The order glslang uses for HLSL (its SpirvToolsTransform), so that the GLSL we emit is what it
    // was when glslang ran these passes itself.
    optimizer.RegisterPass(spvtools::CreateWrapOpKillPass())
        .RegisterPass(spvtools::CreateDeadBranchElimPass())
        .RegisterPass(spvtools::CreateMergeReturnPass())
        .RegisterPass(spvtools::CreateInlineExhaustivePass())
        .RegisterPass(spvtools::CreateEliminateDeadFunctionsPass())
        .RegisterPass(spvtools::CreateScalarReplacementPass())
        .RegisterPass(spvtools::CreateLocalAccessChainConvertPass())
        .RegisterPass(spvtools::CreateLocalSingleBlockLoadStoreElimPass())
        .RegisterPass(spvtools::CreateLocalSingleStoreElimPass())
        .RegisterPass(spvtools::CreateSimplificationPass())
        .RegisterPass(spvtools::CreateAggressiveDCEPass())
        .RegisterPass(spvtools::CreateVectorDCEPass())
        .RegisterPass(spvtools::CreateDeadInsertElimPass())
        .RegisterPass(spvtools::CreateAggressiveDCEPass())
        .RegisterPass(spvtools::CreateDeadBranchElimPass())
        .RegisterPass(spvtools::CreateBlockMergePass())
        .RegisterPass(spvtools::CreateLocalMultiStoreElimPass())
        .RegisterPass(spvtools::CreateIfConversionPass())
        .RegisterPass(spvtools::CreateSimplificationPass())
        .RegisterPass(spvtools::CreateAggressiveDCEPass())
        .RegisterPass(spvtools::CreateVectorDCEPass())
        .RegisterPass(spvtools::CreateDeadInsertElimPass())
        .RegisterPass(spvtools::CreateInterpolateFixupPass())
        .RegisterPass(spvtools::CreateAggressiveDCEPass())
        .RegisterPass(spvtools::CreateCFGCleanupPass());
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

}  // namespace fxport::xlate
