// The SPIR-V module every xlate pass works on (xlate/src/spirv/parsed_spirv.h): what a parse
// records, where new constants go, and how runSpirvPasses hands one parse from pass to pass.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {
namespace {

std::uint32_t op(std::uint32_t opcode, std::uint32_t count) { return count << 16 | opcode; }

// int %1; %2 = 7; void main() { %7 = %2 smod %2; }
std::vector<std::uint32_t> smallModule() {
    return {0x07230203, 0x00010000, 0, 8, 0,
            op(17, 2), 1,              // OpCapability Shader
            op(14, 3), 0, 1,           // OpMemoryModel Logical GLSL450
            op(21, 4), 1, 32, 1,       // %1 = OpTypeInt 32 1
            op(43, 4), 1, 2, 7,        // %2 = OpConstant %1 7
            op(19, 2), 3,              // %3 = OpTypeVoid
            op(33, 3), 4, 3,           // %4 = OpTypeFunction %3
            op(54, 5), 3, 5, 0, 4,     // %5 = OpFunction %3 None %4
            op(248, 2), 6,             // %6 = OpLabel
            op(139, 5), 1, 7, 2, 2,    // %7 = OpSMod %1 %2 %2
            op(253, 1),                // OpReturn
            op(56, 1)};                // OpFunctionEnd
}

TEST(ParsedSpirv, AssemblesWhatItParsedAndKnowsEachId) {
    ParsedSpirv m;
    ASSERT_TRUE(m.parse(smallModule()));
    EXPECT_EQ(m.assemble(), smallModule());
    ASSERT_EQ(m.instructions.size(), 11u);
    EXPECT_EQ(m.firstFunction(), 6u);
    const SpirvInstructionIds& smod = m.ids(8);
    EXPECT_EQ(smod.type, 1u);
    EXPECT_EQ(smod.result, 7u);
    EXPECT_EQ(smod.operands, (std::vector<std::uint16_t>{3, 4}));
    EXPECT_EQ(m.typeOf(7), 1u);
    ASSERT_NE(m.definition(1), nullptr);
    EXPECT_EQ(m.definition(1)->opcode(), spv_op::TypeInt);
    EXPECT_EQ(m.definition(2)->opcode(), spv_op::Constant);
    EXPECT_TRUE(m.has({spv_op::SMod}));
    EXPECT_FALSE(m.has({spv_op::SRem}));
}

TEST(ParsedSpirv, NewConstantsGoBeforeTheFirstFunctionOnce) {
    ParsedSpirv m;
    ASSERT_TRUE(m.parse(smallModule()));
    EXPECT_EQ(m.constant(1, 9), 8u);
    EXPECT_EQ(m.constant(1, 9), 8u);  // added once
    EXPECT_EQ(m.idBound(), 9u);
    std::vector<std::uint32_t> expected = smallModule();
    expected[3] = 9;
    const std::vector<std::uint32_t> constant{op(43, 4), 1, 8, 9};
    expected.insert(expected.begin() + 23, constant.begin(), constant.end());  // before OpFunction
    EXPECT_EQ(m.assemble(), expected);
}

TEST(ParsedSpirv, RunSpirvPassesReadsTheModuleAgainAfterAChange) {
    std::vector<std::uint32_t> words = smallModule();
    int ran = 0;
    auto toSRem = [&](ParsedSpirv& m) {
        ++ran;
        m.instructions[8].words[0] = op(spv_op::SRem, 5);
        m.constant(1, 9);  // held aside until assembled
        return true;
    };
    auto seesSRem = [&](ParsedSpirv& m) {
        ++ran;
        // A fresh parse of the edited words: the new constant is an instruction like any other.
        EXPECT_EQ(m.instructions.size(), 12u);
        EXPECT_TRUE(m.definition(8) && m.definition(8)->opcode() == spv_op::Constant);
        EXPECT_EQ(m.ids(9).result, 7u);
        EXPECT_EQ(m.instructions[9].opcode(), spv_op::SRem);
        return false;
    };
    runSpirvPasses(words, {toSRem, nullptr, seesSRem});
    EXPECT_EQ(ran, 2);
    std::vector<std::uint32_t> expected = smallModule();
    expected[3] = 9;
    expected[30] = op(spv_op::SRem, 5);
    const std::vector<std::uint32_t> constant{op(43, 4), 1, 8, 9};
    expected.insert(expected.begin() + 23, constant.begin(), constant.end());
    EXPECT_EQ(words, expected);
}

TEST(ParsedSpirv, UnparseableWordsAreLeftAloneAndNoPassRuns) {
    std::vector<std::uint32_t> words = smallModule();
    words[10] = op(21, 9);  // OpTypeInt claims 9 words: past the module's end
    const std::vector<std::uint32_t> before = words;
    bool ran = false;
    runSpirvPasses(words, {[&](ParsedSpirv&) { return ran = true; }});
    EXPECT_FALSE(ran);
    EXPECT_EQ(words, before);
}

}  // namespace
}  // namespace fxport::xlate
