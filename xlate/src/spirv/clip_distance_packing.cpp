// SV_ClipDistance / SV_CullDistance elements packed to 0..n-1 (clip_distance_packing.h).
#include "spirv/clip_distance_packing.h"

#include <algorithm>
#include <map>
#include <set>

#include <spirv_cross/spirv.hpp>

namespace fxport::xlate {

namespace {

std::uint32_t opWord(spv::Op op, std::uint32_t count) { return (count << 16) | std::uint32_t(op); }

spv::Op opOf(const SpirvInstruction& in) { return spv::Op(in.opcode()); }

// One built-in array variable to pack, and what the module says about it.
struct DistanceArray {
    std::uint32_t variable = 0;
    std::uint32_t pointerType = 0;  // OpVariable's result type
    spv::StorageClass storage = spv::StorageClassOutput;
    std::uint32_t outerLength = 0;  // arrayed (per-vertex inputs of a geometry shader ...): the outer length id
    std::uint32_t elementType = 0;  // float
    std::uint32_t lengthType = 0;   // the integer type of the inner length constant
    std::uint32_t length = 0;       // the number of distances declared
    std::size_t indexOperand = 0;   // which access-chain index is the distance's: 0, or 1 when arrayed
};

class Packer {
public:
    explicit Packer(ParsedSpirv& m) : m_(m) {
        for (const SpirvInstruction& in : m_.instructions) {
            const auto& w = in.words;
            if (opOf(in) == spv::OpTypePointer && w.size() >= 4) pointers_[w[1]] = {w[2], w[3]};
            if (opOf(in) == spv::OpTypeArray && w.size() >= 4) arrays_[w[1]] = {w[2], w[3]};
            if (opOf(in) == spv::OpConstant && w.size() == 4) constants_[w[2]] = {w[1], w[3]};
        }
    }

    bool run() {
        std::vector<std::uint32_t> variables;
        for (const SpirvInstruction& in : m_.instructions) {
            const auto& w = in.words;
            if (opOf(in) == spv::OpDecorate && w.size() >= 4 && w[2] == spv::DecorationBuiltIn &&
                (w[3] == spv::BuiltInClipDistance || w[3] == spv::BuiltInCullDistance))
                variables.push_back(w[1]);
        }
        bool changed = false;
        for (std::uint32_t v : variables) changed |= pack(v);
        return changed;
    }

private:
    ParsedSpirv& m_;
    std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> pointers_;   // id -> storage, pointee
    std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> arrays_;     // id -> element, length id
    std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> constants_;  // id -> type, value

    // The index of the OpVariable of `id`, or instructions.size().
    std::size_t variableInstruction(std::uint32_t id) const {
        for (std::size_t i = 0; i < m_.instructions.size(); ++i)
            if (opOf(m_.instructions[i]) == spv::OpVariable && m_.instructions[i].word(2) == id) return i;
        return m_.instructions.size();
    }

    bool describe(const SpirvInstruction& var, DistanceArray& d) const {
        d.variable = var.word(2);
        d.pointerType = var.word(1);
        auto pointer = pointers_.find(d.pointerType);
        if (pointer == pointers_.end()) return false;
        d.storage = spv::StorageClass(pointer->second.first);
        auto outer = arrays_.find(pointer->second.second);
        if (outer == arrays_.end()) return false;
        auto inner = arrays_.find(outer->second.first);
        const bool arrayed = inner != arrays_.end();
        const auto& distances = arrayed ? inner->second : outer->second;
        d.outerLength = arrayed ? outer->second.second : 0;
        d.elementType = distances.first;
        auto length = constants_.find(distances.second);
        if (length == constants_.end()) return false;
        d.lengthType = length->second.first;
        d.length = length->second.second;
        d.indexOperand = arrayed ? 1 : 0;
        return true;
    }

    static bool isChain(const SpirvInstruction& in) {
        return opOf(in) == spv::OpAccessChain || opOf(in) == spv::OpInBoundsAccessChain;
    }

    // The constant distance index of every use, or false when a use is anything else.
    bool usedIndices(const DistanceArray& d, std::set<std::uint32_t>& used) const {
        for (std::size_t i = m_.firstFunction(); i < m_.instructions.size(); ++i) {
            const SpirvInstruction& in = m_.instructions[i];
            const auto& w = in.words;
            for (std::size_t k = 1; k < w.size(); ++k) {
                if (w[k] != d.variable) continue;
                if (!isChain(in) || k != 3) return false;  // a load, store or copy of the whole array
                const std::size_t indexAt = 4 + d.indexOperand;
                if (indexAt >= w.size()) return false;  // reaches one vertex's whole array
                auto index = constants_.find(w[indexAt]);
                if (index == constants_.end()) return false;  // a dynamic index
                used.insert(index->second.second);
            }
        }
        return true;
    }

    bool pack(std::uint32_t variable) {
        const std::size_t varAt = variableInstruction(variable);
        DistanceArray d;
        if (varAt == m_.instructions.size() || !describe(m_.instructions[varAt], d)) return false;
        std::set<std::uint32_t> used;
        if (!usedIndices(d, used) || used.empty()) return false;
        const std::uint32_t n = std::uint32_t(used.size());
        if (*used.rbegin() == n - 1 && d.length == n) return false;  // already 0..n-1 and n long
        // New types: the n-element array (inside the outer one when arrayed) and a pointer to it.
        std::vector<SpirvInstruction> added;
        auto emit = [&](spv::Op op, std::initializer_list<std::uint32_t> operands) {
            std::vector<std::uint32_t> words{opWord(op, std::uint32_t(operands.size() + 1))};
            words.insert(words.end(), operands);
            added.push_back({std::move(words)});
        };
        const std::uint32_t length = m_.newId(), inner = m_.newId();
        emit(spv::OpConstant, {d.lengthType, length, n});
        emit(spv::OpTypeArray, {inner, d.elementType, length});
        std::uint32_t pointee = inner;
        if (d.outerLength) {
            pointee = m_.newId();
            emit(spv::OpTypeArray, {pointee, inner, d.outerLength});
        }
        const std::uint32_t pointer = m_.newId();
        emit(spv::OpTypePointer, {pointer, std::uint32_t(d.storage), pointee});
        // The new index constants, each of the type the old one had.
        std::map<std::uint32_t, std::uint32_t> renumbered;  // old index constant id -> new one
        std::uint32_t rank = 0;
        std::map<std::uint32_t, std::uint32_t> rankOf;
        for (std::uint32_t u : used) rankOf[u] = rank++;
        for (std::size_t i = m_.firstFunction(); i < m_.instructions.size(); ++i) {
            SpirvInstruction& in = m_.instructions[i];
            if (!isChain(in) || in.word(3) != variable) continue;
            std::uint32_t& index = in.words[4 + d.indexOperand];
            if (!renumbered.count(index)) {
                const auto& [type, value] = constants_.at(index);
                const std::uint32_t id = m_.newId();
                emit(spv::OpConstant, {type, id, rankOf.at(value)});
                renumbered[index] = id;
            }
            index = renumbered.at(index);
        }
        // The variable moves after the new types (globals may come in any order).
        SpirvInstruction moved = m_.instructions[varAt];
        moved.words[1] = pointer;
        added.push_back(std::move(moved));
        const auto firstFunction = std::ptrdiff_t(m_.firstFunction());
        m_.instructions.insert(m_.instructions.begin() + firstFunction, added.begin(), added.end());
        m_.instructions.erase(m_.instructions.begin() + std::ptrdiff_t(varAt));
        pointers_[pointer] = {std::uint32_t(d.storage), pointee};
        arrays_[inner] = {d.elementType, length};
        if (d.outerLength) arrays_[pointee] = {inner, d.outerLength};
        constants_[length] = {d.lengthType, n};
        for (const auto& [old, fresh] : renumbered) constants_[fresh] = {constants_.at(old).first, rankOf.at(constants_.at(old).second)};
        return true;
    }
};

}  // namespace

bool packClipCullDistances(ParsedSpirv& m) { return Packer(m).run(); }

}  // namespace fxport::xlate
