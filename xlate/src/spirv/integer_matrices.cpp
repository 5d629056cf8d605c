// See integer_matrices.h: int/uint/bool matrices become arrays of their columns.
#include "spirv/integer_matrices.h"

#include <map>

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kTypeBool = 20, kTypeInt = 21, kTypeMatrix = 24, kTypeArray = 28, kConstant = 43, kMemberDecorate = 72,
                        kTranspose = 84, kCompositeConstruct = 80, kCompositeExtract = 81, kIMul = 132, kMatrixTimesScalar = 143,
                        kExtInst = 12, kSelect = 169;
constexpr std::uint32_t kDecRowMajor = 4, kDecColMajor = 5, kDecMatrixStride = 7;

std::uint32_t firstWord(std::uint32_t opcode, size_t count) { return (std::uint32_t(count) << 16) | opcode; }

// Component-wise operations SPIR-V defines on scalars and vectors only: conversions, bitcast,
// arithmetic, logic, select (glslang's conversion of a bool matrix to a float one), comparisons,
// bit operations, and the extended instructions (abs of an int matrix: SAbs; every
// GLSL.std.450 instruction with an int or bool result computes per component).
bool computesPerComponent(std::uint32_t op) {
    return (op >= 109 && op <= 114) || op == 124 || (op >= 126 && op <= 141) || (op >= 164 && op <= 191) || (op >= 194 && op <= 200) ||
           op == kExtInst;
}

struct Shape {
    std::uint32_t column = 0;  // the column vector type
    std::uint32_t count = 0;   // columns
};

class IntegerMatrices {
public:
    explicit IntegerMatrices(ParsedSpirv& m) : m_(m) {
        for (const auto& inst : m_.instructions) {
            if (inst.opcode() != kTypeMatrix || inst.words.size() != 4) continue;
            Shape s{inst.words[2], inst.words[3]};
            matrices_[inst.words[1]] = s;
            const SpirvInstruction* scalar = m_.definition(m_.components(s.column).first);
            if (scalar && (scalar->opcode() == kTypeInt || scalar->opcode() == kTypeBool)) changed_[inst.words[1]] = s;
        }
    }
    bool any() const { return !changed_.empty(); }

    void rewriteOperations() {
        m_.rewrite([&](const SpirvInstruction& inst, std::vector<SpirvInstruction>& out) {
            const auto& w = inst.words;
            bool isValue = w.size() >= 4 && m_.typeOf(w[2]) == w[1];
            if (isValue && inst.opcode() == kTranspose && (changed_.count(w[1]) || changed_.count(m_.typeOf(w[3]))))
                return transpose(inst, out);
            if (isValue && matrices_.count(w[1]) && (computesPerComponent(inst.opcode()) || inst.opcode() == kMatrixTimesScalar) && touchesChanged(inst))
                return perColumn(inst, out);
            out.push_back(inst);
        });
    }

    // The types themselves, and the matrix layout decorations their struct members no longer take.
    void rewriteTypes() {
        std::vector<SpirvInstruction> out;
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> lengths;  // (int type, count) -> constant
        std::uint32_t anyInt = 0;
        for (const auto& inst : m_.instructions) {
            const auto& w = inst.words;
            if (inst.opcode() == kTypeInt && w.size() == 4 && w[2] == 32 && !anyInt) anyInt = w[1];
            if (inst.opcode() == kMemberDecorate && w.size() >= 4 && isLayoutDecoration(w[3]) && memberIsChanged(w[1], w[2])) continue;
            if (inst.opcode() == kTypeMatrix && changed_.count(w[1])) {
                std::uint32_t scalar = m_.components(w[2]).first;
                const SpirvInstruction* s = m_.definition(scalar);
                std::uint32_t intType = s && s->opcode() == kTypeInt ? scalar : anyInt;
                if (!intType) {  // a bool matrix before any int type: one is declared for the length
                    intType = anyInt = m_.newId();
                    out.push_back({{firstWord(kTypeInt, 4), intType, 32, 1}});
                }
                std::uint32_t& length = lengths[{intType, w[3]}];
                if (!length) {
                    length = m_.newId();
                    out.push_back({{firstWord(kConstant, 4), intType, length, w[3]}});
                }
                out.push_back({{firstWord(kTypeArray, 4), w[1], w[2], length}});
                continue;
            }
            out.push_back(inst);
        }
        m_.instructions = std::move(out);
    }

private:
    bool touchesChanged(const SpirvInstruction& inst) const {
        if (changed_.count(inst.words[1])) return true;
        for (size_t k = inst.opcode() == kExtInst ? 5 : 3; k < inst.words.size(); ++k)
            if (changed_.count(m_.typeOf(inst.words[k]))) return true;
        return false;
    }

    std::uint32_t emit(std::vector<SpirvInstruction>& out, std::uint32_t op, std::uint32_t type, const std::vector<std::uint32_t>& operands) {
        out.push_back(m_.value(op, type, operands));
        return out.back().words[2];
    }

    // %r = op %a %b on matrices: the op on each column, the columns put together as %r.
    void perColumn(const SpirvInstruction& inst, std::vector<SpirvInstruction>& out) {
        const auto& w = inst.words;
        Shape result = matrices_.at(w[1]);
        std::vector<std::uint32_t> columns;
        const size_t literals = inst.opcode() == kExtInst ? 2 : 0;  // the set and the instruction
        for (std::uint32_t c = 0; c < result.count; ++c) {
            std::vector<std::uint32_t> operands(w.begin() + 3, w.begin() + 3 + std::ptrdiff_t(literals));
            for (size_t k = 3 + literals; k < w.size(); ++k) {
                auto it = matrices_.find(m_.typeOf(w[k]));
                operands.push_back(it == matrices_.end() ? w[k] : emit(out, kCompositeExtract, it->second.column, {w[k], c}));
            }
            if (inst.opcode() == kMatrixTimesScalar && operands.size() == 2) {  // int matrix * int: IMul by a splat
                std::uint32_t rows = m_.components(result.column).second;
                std::uint32_t splat = emit(out, kCompositeConstruct, result.column, std::vector<std::uint32_t>(rows, operands[1]));
                columns.push_back(emit(out, kIMul, result.column, {operands[0], splat}));
            } else {
                columns.push_back(emit(out, inst.opcode(), result.column, operands));
            }
        }
        construct(w[1], w[2], columns, out);
    }

    // transpose(m): result column j gathers component j of every column of m.
    void transpose(const SpirvInstruction& inst, std::vector<SpirvInstruction>& out) {
        const auto& w = inst.words;
        Shape result = matrices_.at(w[1]), source = matrices_.at(m_.typeOf(w[3]));
        std::uint32_t scalar = m_.components(result.column).first;
        std::vector<std::uint32_t> columns;
        for (std::uint32_t j = 0; j < result.count; ++j) {
            std::vector<std::uint32_t> parts;
            for (std::uint32_t i = 0; i < source.count; ++i) parts.push_back(emit(out, kCompositeExtract, scalar, {w[3], i, j}));
            columns.push_back(emit(out, kCompositeConstruct, result.column, parts));
        }
        construct(w[1], w[2], columns, out);
    }

    void construct(std::uint32_t type, std::uint32_t id, const std::vector<std::uint32_t>& columns, std::vector<SpirvInstruction>& out) {
        std::vector<std::uint32_t> words{firstWord(kCompositeConstruct, 3 + columns.size()), type, id};
        words.insert(words.end(), columns.begin(), columns.end());
        out.push_back({std::move(words)});
    }

    static bool isLayoutDecoration(std::uint32_t d) { return d == kDecRowMajor || d == kDecColMajor || d == kDecMatrixStride; }

    // Whether struct member `k` is a changed matrix, or an array of them.
    bool memberIsChanged(std::uint32_t structId, std::uint32_t k) const {
        const SpirvInstruction* s = m_.definition(structId);
        if (!s || s->words.size() <= 2 + k) return false;
        std::uint32_t type = s->words[2 + k];
        for (const SpirvInstruction* t = m_.definition(type); t && t->opcode() == kTypeArray; t = m_.definition(type)) type = t->words[2];
        return changed_.count(type) > 0;
    }

    ParsedSpirv& m_;
    std::map<std::uint32_t, Shape> matrices_;  // every matrix type
    std::map<std::uint32_t, Shape> changed_;   // those of int or bool columns
};

}  // namespace

bool integerMatricesAsArrays(ParsedSpirv& m) {
    IntegerMatrices pass(m);
    if (!pass.any()) return false;
    pass.rewriteOperations();
    pass.rewriteTypes();
    return true;
}

}  // namespace fxport::xlate
