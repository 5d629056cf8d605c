// See pow2_partitioning.h: pow2 partitioning as integer partitioning with rounded factors.
#include "rewrite/pow2_partitioning.h"

#include <set>

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

std::vector<TextEdit> pow2PartitioningAsInteger(const EffectSyntax& syntax) {
    std::vector<TextEdit> edits;
    const auto& t = syntax.tokens;
    for (size_t i = 1; i + 3 < t.size(); ++i)
        if (t[i - 1].is("[") && t[i].is("partitioning") && t[i + 1].is("(") && t[i + 2].kind == Token::Kind::String &&
            t[i + 2].text == "pow2" && t[i + 3].is(")"))
            edits.push_back({t[i + 2].offset, t[i + 2].end, "\"integer\""});
    return edits;
}

namespace {

constexpr std::uint32_t kOpDecorate = 71, kOpStore = 62, kOpAccessChain = 65, kOpInBoundsAccessChain = 66,
                        kOpTypeArray = 28, kOpCompositeExtract = 81, kOpCompositeConstruct = 80;
constexpr std::uint32_t kDecorationBuiltIn = 11, kBuiltInTessLevelOuter = 11, kBuiltInTessLevelInner = 12;
constexpr std::uint32_t kOpFAdd = 129, kOpFSub = 131, kOpFMul = 133;
constexpr std::uint32_t kGlslCeil = 9, kGlslExp2 = 29, kGlslLog2 = 30, kGlslFMin = 37, kGlslStep = 48;

// The pointers that reach a tessellation-factor variable: the variables and their access chains.
std::set<std::uint32_t> tessFactorPointers(const ParsedSpirv& m) {
    std::set<std::uint32_t> pointers;
    for (const auto& in : m.instructions)
        if (in.opcode() == kOpDecorate && in.words.size() >= 4 && in.words[2] == kDecorationBuiltIn &&
            (in.words[3] == kBuiltInTessLevelOuter || in.words[3] == kBuiltInTessLevelInner))
            pointers.insert(in.words[1]);
    for (const auto& in : m.instructions)
        if ((in.opcode() == kOpAccessChain || in.opcode() == kOpInBoundsAccessChain) && in.words.size() >= 4 &&
            pointers.count(in.words[3]))
            pointers.insert(in.words[2]);
    return pointers;
}

// The power of two at or above the float `x` (at most 64), its instructions appended to `out`:
// r = exp2(ceil(log2(min(x, 64)))), then halved where r/2 >= x and doubled where r < x, so that a
// log2 one ulp off on some GPU cannot make a factor of 4 an 8 (exp2 of an integer is exact). The
// clamp first keeps an infinite factor D3D's 64 (inf - inf would be NaN, which culls).
std::uint32_t roundedUp(ParsedSpirv& m, std::uint32_t floatType, std::uint32_t x, std::vector<SpirvInstruction>& out) {
    const std::uint32_t glsl = m.glslStd450();
    auto op = [&](std::uint32_t opcode, std::vector<std::uint32_t> operands) {
        out.push_back(m.value(opcode, floatType, std::move(operands)));
        return out.back().words[2];
    };
    auto ext = [&](std::uint32_t instruction, std::vector<std::uint32_t> operands) {
        operands.insert(operands.begin(), {glsl, instruction});
        return op(spv_op::ExtInst, std::move(operands));
    };
    const std::uint32_t clamped = ext(kGlslFMin, {x, m.constant(floatType, 0x42800000u)});  // 64.0
    const std::uint32_t r = ext(kGlslExp2, {ext(kGlslCeil, {ext(kGlslLog2, {clamped})})});
    const std::uint32_t half = op(kOpFMul, {r, m.constant(floatType, 0x3F000000u)});     // 0.5
    const std::uint32_t down = op(kOpFSub, {r, op(kOpFMul, {ext(kGlslStep, {clamped, half}), half})});  // half >= x: half
    const std::uint32_t twice = op(kOpFAdd, {down, down});
    return op(kOpFSub, {twice, op(kOpFMul, {ext(kGlslStep, {clamped, down}), down})});  // down < x: 2 down
}

// The rounded value of a store's `value`: a float, or an array of floats element by element; 0 for
// any other type (left as it is).
std::uint32_t roundedValue(ParsedSpirv& m, std::uint32_t value, std::vector<SpirvInstruction>& out) {
    const std::uint32_t type = m.typeOf(value);
    const SpirvInstruction* def = m.definition(type);
    if (!def) return 0;
    if (def->opcode() == spv_op::TypeFloat) return roundedUp(m, type, value, out);
    if (def->opcode() != kOpTypeArray || def->words.size() != 4) return 0;
    const SpirvInstruction* element = m.definition(def->words[2]);
    const SpirvInstruction* length = m.definition(def->words[3]);
    if (!element || element->opcode() != spv_op::TypeFloat || !length || length->opcode() != spv_op::Constant) return 0;
    std::vector<std::uint32_t> parts;
    for (std::uint32_t k = 0; k < length->words[3] && k < 64; ++k) {
        SpirvInstruction e = m.value(kOpCompositeExtract, def->words[2], {value, k});
        out.push_back(e);
        parts.push_back(roundedUp(m, def->words[2], e.words[2], out));
    }
    SpirvInstruction whole = m.value(kOpCompositeConstruct, type, parts);
    out.push_back(whole);
    return whole.words[2];
}

}  // namespace

// Test: runtime D3D11Tessellation pow2 (hull factors 3 and 5 tessellate as 4 and 8).
bool roundTessFactorsToPowersOfTwo(ParsedSpirv& m) {
        const std::set<std::uint32_t> pointers = tessFactorPointers(m);
    if (pointers.empty()) return false;
    m.rewrite([&](const SpirvInstruction& inst, std::vector<SpirvInstruction>& out) {
        if (inst.opcode() != kOpStore || inst.words.size() < 3 || !pointers.count(inst.words[1])) return out.push_back(inst);
        const std::uint32_t rounded = roundedValue(m, inst.words[2], out);
        SpirvInstruction store = inst;
        if (rounded) store.words[2] = rounded;
        out.push_back(store);
    });
    return true;
}

}  // namespace fxport::xlate
