// See reversed_bounds.h.
#include "spirv/reversed_bounds.h"

#include <cstring>
#include <optional>
#include <vector>

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kFMin = 37, kUMin = 38, kSMin = 39, kFMax = 40, kUMax = 41, kSMax = 42;
constexpr std::uint32_t kFClamp = 43, kUClamp = 44, kSClamp = 45, kSmoothStep = 49;
constexpr std::uint32_t kOpFSub = 131, kOpFMul = 133;
constexpr std::uint32_t kOne = 0x3f800000u, kTwo = 0x40000000u, kThree = 0x40400000u;

// Whether `low` and `high` are constants with low < high (strictly, for smoothstep) or low <= high
// in every component, read as `kind` ('f' float, 's' int, 'u' uint).
bool constantsInOrder(const ParsedSpirv& m, std::uint32_t low, std::uint32_t high, char kind, bool strict) {
    auto a = spirvConstantComponents(m, low), b = spirvConstantComponents(m, high);
    if (!a || !b || a->size() != b->size()) return false;
    for (size_t k = 0; k < a->size(); ++k) {
        bool less = false, equal = (*a)[k] == (*b)[k];
        if (kind == 'f') {
            float x, y;
            std::memcpy(&x, &(*a)[k], 4);
            std::memcpy(&y, &(*b)[k], 4);
            less = x < y;
            equal = x == y;
        } else if (kind == 's') {
            less = std::int32_t((*a)[k]) < std::int32_t((*b)[k]);
        } else {
            less = (*a)[k] < (*b)[k];
        }
        if (!(less || (!strict && equal))) return false;
    }
    return true;
}

// `%r = OpExtInst %type %std450 <op> %a %b %c` of the given instruction set, else false.
bool isStd450(const SpirvInstruction& in, std::uint32_t std450, std::uint32_t op) {
    return in.opcode() == spv_op::ExtInst && in.words.size() == 8 && in.words[3] == std450 && in.words[4] == op;
}

bool isFloat32(const ParsedSpirv& m, std::uint32_t type) {
    const SpirvInstruction* c = m.definition(m.components(type).first);
    return c && c->opcode() == spv_op::TypeFloat && c->word(2) == 32;
}

}  // namespace

// Test: xlate RealworldEighthWave.ReversedSmoothstepEdgesComputeFxcsCurve.
bool smoothstepAsFxcArithmetic(ParsedSpirv& m) {
    if (!m.has({spv_op::ExtInst})) return false;
    const std::uint32_t std450 = m.glslStd450();
    bool changed = false;
    m.rewrite([&](const SpirvInstruction& in, std::vector<SpirvInstruction>& out) {
        if (!isStd450(in, std450, kSmoothStep)) return out.push_back(in);
        const std::uint32_t type = in.words[1], a = in.words[5], b = in.words[6], x = in.words[7];
        if (m.typeOf(a) != type || m.typeOf(b) != type || m.typeOf(x) != type || !isFloat32(m, type) ||
            constantsInOrder(m, a, b, 'f', true))
            return out.push_back(in);
        // t = saturate((x - a) / (b - a)); r = t * t * (3 - 2 * t)
        SpirvInstruction num = m.value(kOpFSub, type, {x, a});
        SpirvInstruction den = m.value(kOpFSub, type, {b, a});
        SpirvInstruction q = m.value(spv_op::FDiv, type, {num.words[2], den.words[2]});
        SpirvInstruction t = m.value(spv_op::ExtInst, type, {std450, kFClamp, q.words[2], m.splatConstant(type, 0), m.splatConstant(type, kOne)});
        SpirvInstruction twoT = m.value(kOpFMul, type, {t.words[2], m.splatConstant(type, kTwo)});
        SpirvInstruction s = m.value(kOpFSub, type, {m.splatConstant(type, kThree), twoT.words[2]});
        SpirvInstruction tt = m.value(kOpFMul, type, {t.words[2], t.words[2]});
        SpirvInstruction r = in;
        r.words = {spirvFirstWord(kOpFMul, 5), type, in.words[2], tt.words[2], s.words[2]};
        for (SpirvInstruction* i : {&num, &den, &q, &t, &twoT, &s, &tt}) out.push_back(std::move(*i));
        out.push_back(std::move(r));
        changed = true;
    });
    return changed;
}

// Test: xlate RealworldEighthWave.ReversedClampBoundsGiveTheMaximum.
bool clampAsMinOfMax(ParsedSpirv& m) {
    if (!m.has({spv_op::ExtInst})) return false;
    const std::uint32_t std450 = m.glslStd450();
    bool changed = false;
    m.rewrite([&](const SpirvInstruction& in, std::vector<SpirvInstruction>& out) {
        const bool f = isStd450(in, std450, kFClamp), s = isStd450(in, std450, kSClamp), u = isStd450(in, std450, kUClamp);
        if (!f && !s && !u) return out.push_back(in);
        const std::uint32_t type = in.words[1], x = in.words[5], low = in.words[6], high = in.words[7];
        if (m.typeOf(low) != type || m.typeOf(high) != type || constantsInOrder(m, low, high, f ? 'f' : s ? 's' : 'u', false))
            return out.push_back(in);
        SpirvInstruction lifted = m.value(spv_op::ExtInst, type, {std450, f ? kFMax : s ? kSMax : kUMax, x, low});
        SpirvInstruction r = in;
        r.words = {in.words[0], type, in.words[2], std450, f ? kFMin : s ? kSMin : kUMin, lifted.words[2], high};
        r.words[0] = spirvFirstWord(spv_op::ExtInst, r.words.size());
        out.push_back(std::move(lifted));
        out.push_back(std::move(r));
        changed = true;
    });
    return changed;
}

}  // namespace fxport::xlate
