// A SPIR-V module as a list of instructions, for the fix-ups that add instructions (a constant, an
// operation before another), which the in-place opcode swaps of spirv_fixups.cpp cannot do.
// Parsed with SPIRV-Tools (which knows each opcode's result type and id), edited, assembled back.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace fxport::xlate {

struct SpirvInstruction {
    std::vector<std::uint32_t> words;  // words[0] holds the word count and the opcode
    std::uint32_t opcode() const { return words[0] & 0xFFFFu; }
};

// The SPIR-V opcodes and GLSL.std.450 instructions the fix-ups read or write.
namespace spv_op {
constexpr std::uint32_t ExtInstImport = 11, ConvertFToS = 110, ConvertSToF = 111, ConvertUToF = 112, UDiv = 134,
                        UMod = 137, FDiv = 136, FRem = 140, ExtInst = 12, MemoryModel = 14, TypeInt = 21, TypeFloat = 22,
                        TypeVector = 23, Constant = 43, ConstantComposite = 44, ConstantNull = 46, Function = 54,
                        CopyObject = 83, ConvertFToU = 109, SDiv = 135, SRem = 138, SMod = 139,
                        ShiftRightLogical = 194, ShiftRightArithmetic = 195, ShiftLeftLogical = 196, BitwiseAnd = 199;
}  // namespace spv_op
constexpr std::uint32_t kGlslStd450FMax = 40;

class SpirvModuleEdit {
public:
    // False when SPIRV-Tools cannot parse `words` (the module is then left to the validator).
    bool parse(const std::vector<std::uint32_t>& words);
    std::vector<std::uint32_t> assemble() const;

    std::vector<SpirvInstruction> instructions;  // after the 5-word header

    std::uint32_t newId() { return header_[3]++; }
    // The type id of a value, 0 when it has none; the instruction that defines an id, or null.
    std::uint32_t typeOf(std::uint32_t id) const;
    const SpirvInstruction* definition(std::uint32_t id) const;
    // The component type and count of a scalar or vector type (count 1 for a scalar).
    std::pair<std::uint32_t, std::uint32_t> components(std::uint32_t type) const;

    // A 32-bit constant of a scalar or vector type, every component `value` (added once, before the
    // first function by assemble()); OpConstantNull of `type` for zero.
    std::uint32_t splatConstant(std::uint32_t type, std::uint32_t value);
    // A 32-bit scalar constant (added once) and a composite constant of `parts`.
    std::uint32_t constant(std::uint32_t scalarType, std::uint32_t value);
    std::uint32_t composite(std::uint32_t type, const std::vector<std::uint32_t>& parts);
    // The 32-bit float type of the same shape as `type` (a scalar or vector), found or added.
    std::uint32_t floatTypeLike(std::uint32_t type);
    // The id of the GLSL.std.450 import, added when the module has none.
    std::uint32_t glslStd450();

    // A new value instruction `%id = opcode type operands...` (id and type recorded), to append in
    // rewrite().
    SpirvInstruction value(std::uint32_t opcode, std::uint32_t type, const std::vector<std::uint32_t>& operands);

    // Rebuilds the instruction list: `visit` sees each instruction and appends what replaces it
    // (itself, or instructions before it and then itself) to `out`.
    void rewrite(const std::function<void(const SpirvInstruction&, std::vector<SpirvInstruction>& out)>& visit);

private:
    std::uint32_t addGlobal(std::vector<std::uint32_t> words);  // words[2] is set to a new id
    std::uint32_t addType(std::vector<std::uint32_t> words);    // words[1] is set to a new id
    std::vector<SpirvInstruction> globals_;  // new types and constants, placed by assemble()
    std::vector<SpirvInstruction> types_;    // the new types, for floatTypeLike's look-ups
    SpirvInstruction import_;                // a new GLSL.std.450 import, placed by assemble()
    std::vector<std::uint32_t> header_;
    std::map<std::uint32_t, std::uint32_t> typeOf_;
    std::map<std::uint32_t, size_t> definedAt_;  // id -> index in `instructions`
    std::map<std::tuple<std::uint32_t, std::uint32_t>, std::uint32_t> splats_, constants_;
    std::uint32_t glslStd450_ = 0;
    void index();
};

}  // namespace fxport::xlate
