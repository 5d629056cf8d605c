// See spirv_integer_fixups.h: D3D's meaning of shifts, float-to-uint conversion and INT_MIN / -1.
#include "spirv/spirv_integer_fixups.h"

#include <climits>
#include <optional>


namespace fxport::xlate {

namespace {

bool isShift(std::uint32_t op) {
    return op == spv_op::ShiftLeftLogical || op == spv_op::ShiftRightLogical || op == spv_op::ShiftRightArithmetic;
}

}  // namespace

// Test: runtime HlslIntegerOps.ShiftCountsUseTheirLowFiveBits, conformance bitwise.
bool maskShiftCounts(ParsedSpirv& m) {
    if (!m.has({spv_op::ShiftLeftLogical, spv_op::ShiftRightLogical, spv_op::ShiftRightArithmetic})) return false;
    m.rewrite([&](const SpirvInstruction& inst, std::vector<SpirvInstruction>& out) {
        if (!isShift(inst.opcode()) || inst.words.size() != 5) return out.push_back(inst);
        const std::uint32_t count = inst.words[4];
        bool small = false;  // a constant count below 32 (`x << 2`) stays as it is
        if (auto c = spirvConstantComponents(m, count)) {
            small = true;
            for (std::uint32_t v : *c) small = small && v < 32;
        }
        if (small) return out.push_back(inst);
        const std::uint32_t type = m.typeOf(count);
        SpirvInstruction mask = m.value(spv_op::BitwiseAnd, type, {count, m.splatConstant(type, 31)});
        SpirvInstruction shift = inst;
        shift.words[4] = mask.words[2];
        out.push_back(mask);
        out.push_back(shift);
    });
    return true;
}

// Test: runtime HlslIntegerOps.NegativeFloatToUintIsZero, conformance cast-to-uint.
bool floatToUnsignedSaturates(ParsedSpirv& m) {
    if (!m.has({spv_op::ConvertFToU})) return false;
    m.rewrite([&](const SpirvInstruction& inst, std::vector<SpirvInstruction>& out) {
        if (inst.opcode() != spv_op::ConvertFToU || inst.words.size() != 4) return out.push_back(inst);
        const std::uint32_t x = inst.words[3], type = m.typeOf(x);
        SpirvInstruction clamped =
            m.value(spv_op::ExtInst, type, {m.glslStd450(), kGlslStd450FMax, x, m.splatConstant(type, 0)});
        SpirvInstruction convert = inst;
        convert.words[3] = clamped.words[2];
        out.push_back(clamped);
        out.push_back(convert);
    });
    return true;
}

// Test: runtime HlslIntegerOps.IntMinByMinusOneFolds, conformance arithmetic-int.
bool foldIntMinByMinusOne(ParsedSpirv& m) {
    if (!m.has({spv_op::SDiv, spv_op::SRem})) return false;
    bool changed = false;
    m.rewrite([&](const SpirvInstruction& inst, std::vector<SpirvInstruction>& out) {
        const std::uint32_t op = inst.opcode();
        if ((op != spv_op::SDiv && op != spv_op::SRem) || inst.words.size() != 5)
            return out.push_back(inst);
        auto a = spirvConstantComponents(m, inst.words[3]), b = spirvConstantComponents(m, inst.words[4]);
        if (!a || !b || a->size() != b->size()) return out.push_back(inst);
        bool trap = false;
        for (size_t k = 0; k < a->size(); ++k) {
            if ((*b)[k] == 0) return out.push_back(inst);  // dividesByConstantZero's refusal, not ours
            trap = trap || ((*a)[k] == 0x80000000u && (*b)[k] == 0xFFFFFFFFu);
        }
        if (!trap) return out.push_back(inst);
        // Every component as D3D's idiv computes it (truncating; INT_MIN / -1 wraps to INT_MIN).
        std::vector<std::uint32_t> result;
        for (size_t k = 0; k < a->size(); ++k) {
            const long long x = std::int32_t((*a)[k]), y = std::int32_t((*b)[k]);
            const long long r = op == spv_op::SDiv ? x / y : x % y;
            result.push_back(std::uint32_t(std::int32_t(r == 0x80000000LL ? INT_MIN : r)));
        }
        const std::uint32_t type = inst.words[1];
        auto [component, count] = m.components(type);
        std::uint32_t folded = 0;
        if (count == 1) {
            folded = m.constant(component, result[0]);
        } else {
            std::vector<std::uint32_t> parts;
            for (std::uint32_t v : result) parts.push_back(m.constant(component, v));
            folded = m.composite(type, parts);
        }
        SpirvInstruction copy = inst;
        copy.words = {(4u << 16) | spv_op::CopyObject, type, inst.words[2], folded};
        out.push_back(copy);
        changed = true;
    });
    return changed;
}

// Test: runtime HlslSm3Integers.DivisionRoundsOperandsToFloat, conformance arithmetic-int-uniform.
bool integerDivisionInFloats(ParsedSpirv& m) {
    if (!m.has({spv_op::SDiv, spv_op::UDiv, spv_op::SRem, spv_op::UMod})) return false;
    m.rewrite([&](const SpirvInstruction& inst, std::vector<SpirvInstruction>& out) {
        const std::uint32_t op = inst.opcode();
        const bool isSigned = op == spv_op::SDiv || op == spv_op::SRem, isDivision = op == spv_op::SDiv || op == spv_op::UDiv;
        if ((!isSigned && op != spv_op::UDiv && op != spv_op::UMod) || inst.words.size() != 5) return out.push_back(inst);
        const std::uint32_t type = inst.words[1], floatType = m.floatTypeLike(type);
        const std::uint32_t toFloat = isSigned ? spv_op::ConvertSToF : spv_op::ConvertUToF;
        SpirvInstruction a = m.value(toFloat, floatType, {inst.words[3]});
        SpirvInstruction b = m.value(toFloat, floatType, {inst.words[4]});
        SpirvInstruction q = m.value(isDivision ? spv_op::FDiv : spv_op::FRem, floatType, {a.words[2], b.words[2]});
        SpirvInstruction back = inst;  // keeps the result id
        back.words = {(4u << 16) | (isSigned ? spv_op::ConvertFToS : spv_op::ConvertFToU), type, inst.words[2], q.words[2]};
        out.insert(out.end(), {a, b, q, back});
    });
    return true;
}

bool integerNegationInFloats(ParsedSpirv& m) {
    constexpr std::uint32_t kOpSNegate = 126, kOpFNegate = 127;
    if (!m.has({kOpSNegate})) return false;
    m.rewrite([&](const SpirvInstruction& inst, std::vector<SpirvInstruction>& out) {
        if (inst.opcode() != kOpSNegate || inst.words.size() != 4) return out.push_back(inst);
        const std::uint32_t type = inst.words[1], floatType = m.floatTypeLike(type);
        SpirvInstruction a = m.value(spv_op::ConvertSToF, floatType, {inst.words[3]});
        SpirvInstruction n = m.value(kOpFNegate, floatType, {a.words[2]});
        SpirvInstruction back = inst;  // keeps the result id
        back.words = {(4u << 16) | spv_op::ConvertFToS, type, inst.words[2], n.words[2]};
        out.insert(out.end(), {a, n, back});
    });
    return true;
}

}  // namespace fxport::xlate

namespace fxport::xlate {

// Test: runtime HlslSm3Integers.ValuesBeyondInt32StayFloats, conformance arithmetic-int.
bool intMinByMinusOneInFloats(ParsedSpirv& m) {
    if (!m.has({spv_op::SDiv})) return false;
    bool changed = false;
    m.rewrite([&](const SpirvInstruction& inst, std::vector<SpirvInstruction>& out) {
        if (inst.opcode() != spv_op::SDiv || inst.words.size() != 5) return out.push_back(inst);
        auto a = spirvConstantComponents(m, inst.words[3]), b = spirvConstantComponents(m, inst.words[4]);
        if (!a || !b || a->size() != b->size()) return out.push_back(inst);
        bool overflows = false;
        for (size_t k = 0; k < a->size(); ++k) overflows = overflows || ((*a)[k] == 0x80000000u && (*b)[k] == 0xFFFFFFFFu);
        if (!overflows) return out.push_back(inst);
        const std::uint32_t type = inst.words[1], floatType = m.floatTypeLike(type);
        SpirvInstruction x = m.value(spv_op::ConvertSToF, floatType, {inst.words[3]});
        SpirvInstruction y = m.value(spv_op::ConvertSToF, floatType, {inst.words[4]});
        SpirvInstruction q = m.value(spv_op::FDiv, floatType, {x.words[2], y.words[2]});
        SpirvInstruction back = inst;  // keeps the result id; a float reader of it sees q (integerCastsOfFloatIntegers)
        back.words = {(4u << 16) | spv_op::ConvertFToS, type, inst.words[2], q.words[2]};
        out.insert(out.end(), {x, y, q, back});
        changed = true;
    });
    return changed;
}

// Test: runtime HlslSm3Integers.ValuesBeyondInt32StayFloats, conformance arithmetic-int, cast-to-int.
bool integerCastsOfFloatIntegers(ParsedSpirv& m) {
    constexpr std::uint32_t kOpCompositeConstruct = 80, kOpBitcast = 124, kGlslStd450Trunc = 3;
    if (!m.has({spv_op::ConvertSToF})) return false;
    bool changed = false;
    m.rewrite([&](const SpirvInstruction& inst, std::vector<SpirvInstruction>& out) {
        if (inst.opcode() != spv_op::ConvertSToF || inst.words.size() != 4) return out.push_back(inst);
        const std::uint32_t type = inst.words[1], operand = inst.words[3];
        const SpirvInstruction* d = m.definition(operand);
        if (!d || d->words.size() < 4) return out.push_back(inst);
        SpirvInstruction r = inst;
        if (d->opcode() == spv_op::ConvertFToS && m.typeOf(d->words[3]) == type) {
            // float(int(f)): the int is f truncated, kept as the float it is.
            r.words = {spirvFirstWord(spv_op::ExtInst, 6), type, inst.words[2], m.glslStd450(), kGlslStd450Trunc, d->words[3]};
        } else if (d->opcode() == kOpBitcast && d->words.size() == 4) {
            // float((int)u) of a uint u: the same float as u.
            const SpirvInstruction* from = m.definition(m.components(m.typeOf(d->words[3])).first);
            if (!from || from->opcode() != spv_op::TypeInt || from->word(3) != 0) return out.push_back(inst);
            r.words = {spirvFirstWord(spv_op::ConvertUToF, 4), type, inst.words[2], d->words[3]};
        } else if (d->opcode() == kOpCompositeConstruct && m.components(type).second == d->words.size() - 3) {
            // float4(int4(a, b, ...)) of scalars: each converted on its own, so the rules above meet it.
            const std::uint32_t scalar = m.components(type).first;
            for (size_t k = 3; k < d->words.size(); ++k)
                if (m.components(m.typeOf(d->words[k])).second != 1) return out.push_back(inst);
            std::vector<std::uint32_t> parts;
            for (size_t k = 3; k < d->words.size(); ++k) {
                SpirvInstruction part = m.value(spv_op::ConvertSToF, scalar, {d->words[k]});
                parts.push_back(part.words[2]);
                out.push_back(std::move(part));
            }
            r.words = {spirvFirstWord(kOpCompositeConstruct, 3 + parts.size()), type, inst.words[2]};
            r.words.insert(r.words.end(), parts.begin(), parts.end());
        } else {
            return out.push_back(inst);
        }
        out.push_back(std::move(r));
        changed = true;
    });
    return changed;
}

}  // namespace fxport::xlate
