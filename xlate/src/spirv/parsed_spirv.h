// A SPIR-V module as a list of instructions: the one representation every SPIR-V pass of xlate
// works on (spirv_passes.h runs them). Parsed once with SPIRV-Tools, which knows each opcode's
// result type, result id and id operands; edited in place or rebuilt by rewrite(); assembled back.
#pragma once

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

namespace fxport::xlate {

struct SpirvInstruction {
    std::vector<std::uint32_t> words;  // words[0] holds the word count and the opcode
    std::uint32_t opcode() const { return words[0] & 0xFFFFu; }
    // Word k, 0 past the end (so that a short, malformed instruction reads as zeros).
    std::uint32_t word(size_t k) const { return k < words.size() ? words[k] : 0; }
};

// What the parse found in one instruction; valid until the module is edited (see ids()).
struct SpirvInstructionIds {
    std::uint32_t type = 0;
    std::uint32_t result = 0;
    std::vector<std::uint16_t> operands;  // word indices of the ids it reads (memory-semantics and scope ids too)
};

// The SPIR-V opcodes and GLSL.std.450 instructions the passes read or write.
namespace spv_op {
constexpr std::uint32_t Name = 5, MemberName = 6, ExtInstImport = 11, ExtInst = 12, MemoryModel = 14, TypeBool = 20,
                        TypeInt = 21, TypeFloat = 22, TypeVector = 23, Constant = 43, ConstantComposite = 44,
                        ConstantNull = 46, Function = 54, CopyObject = 83, ConvertFToU = 109, ConvertFToS = 110,
                        ConvertSToF = 111, ConvertUToF = 112, SNegate = 126, FNegate = 127, UDiv = 134, SDiv = 135,
                        FDiv = 136, UMod = 137, SRem = 138, SMod = 139, FRem = 140, FMod = 141, Any = 154, All = 155,
                        LogicalNot = 168, ShiftRightLogical = 194, ShiftRightArithmetic = 195, ShiftLeftLogical = 196,
                        BitwiseAnd = 199;
}  // namespace spv_op
constexpr std::uint32_t kGlslStd450FMax = 40;

// The first word of an instruction of `count` words.
inline std::uint32_t spirvFirstWord(std::uint32_t opcode, size_t count) { return (std::uint32_t(count) << 16) | opcode; }

// SPIR-V's literal string starting at word `first` of `in`: UTF-8, the first byte in a word's lowest
// byte, NUL-terminated (what OpName, OpExtension and OpDecorateString carry).
std::string spirvLiteralString(const SpirvInstruction& in, size_t first);
// `s` as the words of a literal string (NUL-terminated, padded to a whole word).
std::vector<std::uint32_t> spirvLiteralWords(const std::string& s);

class ParsedSpirv {
public:
    // False when SPIRV-Tools cannot parse `words` (the module is then left to the validator).
    bool parse(const std::vector<std::uint32_t>& words);
    std::vector<std::uint32_t> assemble() const;
    // Assembles and parses again, so that ids(), typeOf() and definition() describe the edited
    // module exactly as a fresh parse of its words would (new types and constants in place);
    // false, and the module as it was, when SPIRV-Tools cannot parse the result.
    bool reparse();

    std::vector<SpirvInstruction> instructions;  // after the 5-word header

    // Whether an instruction with one of `opcodes` occurs (passes that cannot apply cost a scan).
    bool has(std::initializer_list<std::uint32_t> opcodes) const;
    // The parse's type, result and id operands of instructions[index]: only for a module unedited
    // since the last parse() or reparse() (rewrite() drops them: nothing is found after it).
    const SpirvInstructionIds& ids(size_t index) const;
    // The index of the first OpFunction, instructions.size() when there is none.
    size_t firstFunction() const;

    std::uint32_t newId() { return header_[3]++; }
    // The header's id bound (every id is below it), for a pass that numbers new ids itself.
    std::uint32_t idBound() const { return header_[3]; }
    void setIdBound(std::uint32_t bound) { header_[3] = bound; }
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
    // The bool type of the same shape as `type` (a scalar or vector), found or added.
    std::uint32_t boolTypeLike(std::uint32_t type);
    // The 32-bit signed and unsigned integer types, found or added.
    std::uint32_t intType();
    std::uint32_t uintType();
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
    std::uint32_t findType(const std::function<bool(const SpirvInstruction&)>& match) const;  // 0 when none
    std::uint32_t vectorLike(std::uint32_t scalar, std::uint32_t type);  // `scalar`'s vector as wide as `type`
    std::vector<SpirvInstruction> globals_;  // new types and constants, placed by assemble()
    std::vector<SpirvInstruction> types_;    // the new types, for floatTypeLike's look-ups
    SpirvInstruction import_;                // a new GLSL.std.450 import, placed by assemble()
    std::vector<std::uint32_t> header_;
    std::vector<SpirvInstructionIds> ids_;
    std::map<std::uint32_t, std::uint32_t> typeOf_;
    std::map<std::uint32_t, size_t> definedAt_;  // id -> index in `instructions`
    std::map<std::tuple<std::uint32_t, std::uint32_t>, std::uint32_t> splats_, constants_;
    std::uint32_t glslStd450_ = 0;
    void index();
};

// A pass over a module: edits it, returns whether it changed anything.
using SpirvPass = std::function<bool(ParsedSpirv&)>;

// Runs `passes` in order (an empty one is skipped). After a pass that changed the module it is read
// again (reparse()), so that the next pass sees ids, types and definitions as a fresh parse of
// the edited words would; the passes after one whose result SPIRV-Tools cannot read are skipped.
// True when a pass changed the module.
bool runSpirvPasses(ParsedSpirv& m, const std::vector<SpirvPass>& passes);
// The same on `words`, parsed once; they are replaced by the edited module when a pass changed it,
// and left alone (no pass runs) when SPIRV-Tools cannot parse them.
void runSpirvPasses(std::vector<std::uint32_t>& words, const std::vector<SpirvPass>& passes);

// The 32-bit components of a constant scalar or vector (OpConstant, OpConstantComposite of them,
// OpConstantNull); nothing when `id` is not such a constant.
std::optional<std::vector<std::uint32_t>> spirvConstantComponents(const ParsedSpirv& m, std::uint32_t id);

}  // namespace fxport::xlate
