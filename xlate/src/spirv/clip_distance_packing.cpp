// SV_ClipDistance / SV_CullDistance elements packed to 0..n-1 (clip_distance_packing.h).
#include "spirv/clip_distance_packing.h"

#include <algorithm>
#include <map>
#include <set>

#include <spirv_cross/spirv.hpp>

namespace fxport::xlate {

namespace {

constexpr std::size_t kHeaderWords = 5;

struct Instruction {
    std::size_t at;  // index of its first word
    spv::Op op;
    std::uint32_t count;
};

// Every instruction of the module, in order.
std::vector<Instruction> instructionsOf(const std::vector<std::uint32_t>& words) {
    std::vector<Instruction> out;
    for (std::size_t i = kHeaderWords; i < words.size();) {
        const std::uint32_t count = words[i] >> 16;
        if (count == 0 || i + count > words.size()) return {};  // malformed: touch nothing
        out.push_back({i, spv::Op(words[i] & 0xFFFFu), count});
        i += count;
    }
    return out;
}

std::uint32_t opWord(spv::Op op, std::uint32_t count) { return (count << 16) | std::uint32_t(op); }

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
    explicit Packer(std::vector<std::uint32_t>& words) : words_(words), code_(instructionsOf(words)) {
        for (const Instruction& in : code_) {
            const std::uint32_t* w = &words_[in.at];
            if (in.op == spv::OpTypePointer) pointers_[w[1]] = {w[2], w[3]};
            if (in.op == spv::OpTypeArray) arrays_[w[1]] = {w[2], w[3]};
            if (in.op == spv::OpConstant && in.count == 4) constants_[w[2]] = {w[1], w[3]};
        }
    }

    void run() {
        std::vector<std::uint32_t> variables;
        for (const Instruction& in : code_) {
            const std::uint32_t* w = &words_[in.at];
            if (in.op == spv::OpDecorate && in.count >= 4 && w[2] == spv::DecorationBuiltIn &&
                (w[3] == spv::BuiltInClipDistance || w[3] == spv::BuiltInCullDistance))
                variables.push_back(w[1]);
        }
        for (std::uint32_t v : variables) pack(v);
    }

private:
    std::vector<std::uint32_t>& words_;
    std::vector<Instruction> code_;
    std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> pointers_;   // id -> storage, pointee
    std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> arrays_;     // id -> element, length id
    std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> constants_;  // id -> type, value

    const Instruction* variableInstruction(std::uint32_t id) const {
        for (const Instruction& in : code_)
            if (in.op == spv::OpVariable && words_[in.at + 2] == id) return &in;
        return nullptr;
    }

    bool describe(const Instruction& var, DistanceArray& d) const {
        d.variable = words_[var.at + 2];
        d.pointerType = words_[var.at + 1];
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

    // The constant distance index of every use, or false when a use is anything else.
    bool usedIndices(const DistanceArray& d, std::set<std::uint32_t>& used) const {
        bool inFunctions = false;
        for (const Instruction& in : code_) {
            if (in.op == spv::OpFunction) inFunctions = true;
            if (!inFunctions) continue;
            const std::uint32_t* w = &words_[in.at];
            const bool chain = in.op == spv::OpAccessChain || in.op == spv::OpInBoundsAccessChain;
            for (std::uint32_t k = 1; k < in.count; ++k) {
                if (w[k] != d.variable) continue;
                if (!chain || k != 3) return false;  // a load, store or copy of the whole array
                const std::uint32_t indexAt = 4 + std::uint32_t(d.indexOperand);
                if (indexAt >= in.count) return false;  // reaches one vertex's whole array
                auto index = constants_.find(w[indexAt]);
                if (index == constants_.end()) return false;  // a dynamic index
                used.insert(index->second.second);
            }
        }
        return true;
    }

    std::uint32_t newId() { return words_[3]++; }

    void pack(std::uint32_t variable) {
        const Instruction* var = variableInstruction(variable);
        DistanceArray d;
        if (!var || !describe(*var, d)) return;
        std::set<std::uint32_t> used;
        if (!usedIndices(d, used) || used.empty()) return;
        const std::uint32_t n = std::uint32_t(used.size());
        if (*used.rbegin() == n - 1 && d.length == n) return;  // already 0..n-1 and n long
        // New types: the n-element array (inside the outer one when arrayed) and a pointer to it.
        std::vector<std::uint32_t> added;
        auto emit = [&](spv::Op op, std::initializer_list<std::uint32_t> operands) {
            added.push_back(opWord(op, std::uint32_t(operands.size() + 1)));
            added.insert(added.end(), operands);
        };
        const std::uint32_t length = newId(), inner = newId();
        emit(spv::OpConstant, {d.lengthType, length, n});
        emit(spv::OpTypeArray, {inner, d.elementType, length});
        std::uint32_t pointee = inner;
        if (d.outerLength) {
            pointee = newId();
            emit(spv::OpTypeArray, {pointee, inner, d.outerLength});
        }
        const std::uint32_t pointer = newId();
        emit(spv::OpTypePointer, {pointer, std::uint32_t(d.storage), pointee});
        // The new index constants, each of the type the old one had.
        std::map<std::uint32_t, std::uint32_t> renumbered;  // old index constant id -> new one
        std::uint32_t rank = 0;
        std::map<std::uint32_t, std::uint32_t> rankOf;
        for (std::uint32_t u : used) rankOf[u] = rank++;
        bool inFunctions = false;
        for (const Instruction& in : code_) {
            if (in.op == spv::OpFunction) inFunctions = true;
            const bool chain = in.op == spv::OpAccessChain || in.op == spv::OpInBoundsAccessChain;
            if (!inFunctions || !chain || words_[in.at + 3] != variable) continue;
            std::uint32_t& index = words_[in.at + 4 + d.indexOperand];
            if (!renumbered.count(index)) {
                const auto& [type, value] = constants_.at(index);
                const std::uint32_t id = newId();
                emit(spv::OpConstant, {type, id, rankOf.at(value)});
                renumbered[index] = id;
            }
            index = renumbered.at(index);
        }
        // The variable moves after the new types (globals may come in any order).
        std::vector<std::uint32_t> variableWords(words_.begin() + std::ptrdiff_t(var->at), words_.begin() + std::ptrdiff_t(var->at + var->count));
        variableWords[1] = pointer;
        added.insert(added.end(), variableWords.begin(), variableWords.end());
        std::size_t firstFunction = words_.size();
        for (const Instruction& in : code_)
            if (in.op == spv::OpFunction) {
                firstFunction = in.at;
                break;
            }
        words_.insert(words_.begin() + std::ptrdiff_t(firstFunction), added.begin(), added.end());
        words_.erase(words_.begin() + std::ptrdiff_t(var->at), words_.begin() + std::ptrdiff_t(var->at + var->count));
        // Offsets moved: read the module again for the next variable.
        code_ = instructionsOf(words_);
        pointers_[pointer] = {std::uint32_t(d.storage), pointee};
        arrays_[inner] = {d.elementType, length};
        if (d.outerLength) arrays_[pointee] = {inner, d.outerLength};
        constants_[length] = {d.lengthType, n};
        for (const auto& [old, fresh] : renumbered) constants_[fresh] = {constants_.at(old).first, rankOf.at(constants_.at(old).second)};
    }
};

}  // namespace

void packClipCullDistances(std::vector<std::uint32_t>& words) {
    if (words.size() <= kHeaderWords) return;
    Packer(words).run();
}

}  // namespace fxport::xlate
