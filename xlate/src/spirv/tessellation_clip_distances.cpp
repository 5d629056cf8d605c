// Hull inputs and domain outputs of FXPORT_CLIPDISTANCEn / FXPORT_CULLDISTANCEn as GL's built-ins
// (tessellation_clip_distances.h).
#include "spirv/tessellation_clip_distances.h"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>

#include <spirv_cross/spirv.hpp>

#include "fx/text_util.h"
#include "rewrite/tessellation_clip_semantics.h"

namespace fxport::xlate {

namespace {

SpirvInstruction make(spv::Op op, std::initializer_list<std::uint32_t> operands) {
    std::vector<std::uint32_t> words{spirvFirstWord(std::uint32_t(op), operands.size() + 1)};
    words.insert(words.end(), operands);
    return {std::move(words)};
}

// One varying to replace.
struct Distance {
    std::uint32_t variable = 0;
    std::uint32_t pointee = 0;     // the variable's type: T, or T[vertices] for a hull input
    std::uint32_t valueType = 0;   // T: float or a float vector
    std::uint32_t components = 1;
    std::uint32_t vertices = 0;    // hull inputs: the patch's control points
    bool cull = false;
    int semanticIndex = 0;
    std::uint32_t first = 0;       // its first element in the built-in array
};

bool isAnnotation(std::uint32_t op) {
    return op == spv::OpDecorate || op == spv::OpMemberDecorate || op == spv::OpDecorateString ||
           op == spv::OpMemberDecorateString || op == spv::OpDecorationGroup || op == spv::OpGroupDecorate ||
           op == spv::OpDecorateId;
}

class Converter {
public:
    explicit Converter(ParsedSpirv& m) : m_(m) {}

    bool run() {
        if (!findEntry()) return false;
        collectTypes();
        if (!collectDistances()) return false;
        std::vector<SpirvInstruction> globals = declare();
        edit(std::move(globals));
        return true;
    }

private:
    ParsedSpirv& m_;
    bool hull_ = false;
    std::uint32_t entryFunction_ = 0;
    spv::StorageClass storage_ = spv::StorageClassOutput;  // of the varyings replaced
    std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> pointers_;  // id -> storage, pointee
    std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> arrays_;    // id -> element, length id
    std::map<std::uint32_t, std::pair<std::uint32_t, std::uint32_t>> vectors_;   // id -> component, count
    std::map<std::uint32_t, std::uint32_t> constants_;                          // 32-bit constant id -> value
    std::set<std::uint32_t> floats_;                                            // 32-bit float types
    std::uint32_t intType_ = 0;
    std::vector<Distance> distances_;
    // Made by declare():
    std::uint32_t floatType_ = 0;
    std::map<bool, std::uint32_t> builtin_;   // cull? -> the built-in variable
    std::uint32_t elementPointer_ = 0;        // pointer (storage_) to one float of the built-in
    std::map<std::uint32_t, std::uint32_t> privatePointer_;  // pointee -> Private pointer type
    std::map<std::uint32_t, std::uint32_t> index_;           // value -> int constant

    bool findEntry() {
        for (const SpirvInstruction& in : m_.instructions) {
            if (in.opcode() != spv::OpEntryPoint) continue;
            if (in.word(1) != spv::ExecutionModelTessellationControl && in.word(1) != spv::ExecutionModelTessellationEvaluation)
                return false;
            hull_ = in.word(1) == spv::ExecutionModelTessellationControl;
            entryFunction_ = in.word(2);
            storage_ = hull_ ? spv::StorageClassInput : spv::StorageClassOutput;
            return true;
        }
        return false;
    }

    void collectTypes() {
        for (const SpirvInstruction& in : m_.instructions) {
            const auto& w = in.words;
            switch (in.opcode()) {
            case spv::OpTypePointer: pointers_[in.word(1)] = {in.word(2), in.word(3)}; break;
            case spv::OpTypeArray: arrays_[in.word(1)] = {in.word(2), in.word(3)}; break;
            case spv::OpTypeVector: vectors_[in.word(1)] = {in.word(2), in.word(3)}; break;
            case spv::OpTypeFloat:
                if (in.word(2) == 32) floats_.insert(in.word(1));
                break;
            case spv::OpTypeInt:
                if (in.word(2) == 32 && (!intType_ || in.word(3) == 1)) intType_ = in.word(1);
                break;
            case spv::OpConstant:
                if (w.size() == 4) constants_[in.word(2)] = in.word(3);
                break;
            default: break;
            }
        }
    }

    // The varyings the rewrite renamed that meet a GL built-in here, in order of semantic index.
    bool collectDistances() {
        std::map<std::uint32_t, std::pair<bool, int>> semantics;  // variable -> cull?, index
        for (const SpirvInstruction& in : m_.instructions) {
            if (in.opcode() != spv::OpDecorateString || in.word(2) != spv::DecorationUserSemantic) continue;
            const std::string s = toUpper(spirvLiteralString(in, 3));
            for (const auto& [prefix, cull] : {std::pair<std::string, bool>{kTessellationClipSemantic, false}, {kTessellationCullSemantic, true}})
                if (s.rfind(prefix, 0) == 0 && s.size() > prefix.size())
                    semantics[in.word(1)] = {cull, std::atoi(s.c_str() + prefix.size())};
        }
        for (const SpirvInstruction& in : m_.instructions) {
            if (in.opcode() != spv::OpVariable || in.word(3) != std::uint32_t(storage_)) continue;
            auto semantic = semantics.find(in.word(2));
            auto pointer = pointers_.find(in.word(1));
            if (semantic == semantics.end() || pointer == pointers_.end()) continue;
            Distance d;
            d.variable = in.word(2);
            d.pointee = d.valueType = pointer->second.second;
            d.cull = semantic->second.first;
            d.semanticIndex = semantic->second.second;
            if (hull_) {
                auto array = arrays_.find(d.pointee);
                if (array == arrays_.end() || !constants_.count(array->second.second)) continue;
                d.valueType = array->second.first;
                d.vertices = constants_.at(array->second.second);
            }
            std::uint32_t component = d.valueType;
            if (auto v = vectors_.find(d.valueType); v != vectors_.end()) std::tie(component, d.components) = v->second;
            if (!floats_.count(component)) continue;  // an array of distances: left a user varying
            floatType_ = component;
            distances_.push_back(d);
        }
        if (distances_.empty() || !intType_) return false;
        std::stable_sort(distances_.begin(), distances_.end(),
                         [](const Distance& a, const Distance& b) { return a.semanticIndex < b.semanticIndex; });
        std::map<bool, std::uint32_t> next;
        for (Distance& d : distances_) {
            d.first = next[d.cull];
            next[d.cull] += d.components;
        }
        return true;
    }

    std::uint32_t indexConstant(std::vector<SpirvInstruction>& globals, std::uint32_t value) {
        auto it = index_.find(value);
        if (it != index_.end()) return it->second;
        const std::uint32_t id = m_.newId();
        globals.push_back(make(spv::OpConstant, {intType_, id, value}));
        return index_[value] = id;
    }

    std::uint32_t privatePointer(std::vector<SpirvInstruction>& globals, std::uint32_t pointee) {
        auto it = privatePointer_.find(pointee);
        if (it != privatePointer_.end()) return it->second;
        const std::uint32_t id = m_.newId();
        globals.push_back(make(spv::OpTypePointer, {id, spv::StorageClassPrivate, pointee}));
        return privatePointer_[pointee] = id;
    }

    // The new types, constants and variables (placed before the first function): the built-in
    // arrays, and each varying again as a Private variable of the same id.
    std::vector<SpirvInstruction> declare() {
        std::vector<SpirvInstruction> g;
        std::map<bool, std::uint32_t> length;
        for (const Distance& d : distances_) length[d.cull] = std::max(length[d.cull], d.first + d.components);
        for (const Distance& d : distances_) indexConstant(g, d.vertices);
        for (const auto& [cull, n] : length) {
            const std::uint32_t array = m_.newId();
            g.push_back(make(spv::OpTypeArray, {array, floatType_, indexConstant(g, n)}));
            std::uint32_t pointee = array;
            if (hull_) {
                pointee = m_.newId();
                g.push_back(make(spv::OpTypeArray, {pointee, array, indexConstant(g, distances_.front().vertices)}));
            }
            const std::uint32_t pointer = m_.newId();
            g.push_back(make(spv::OpTypePointer, {pointer, std::uint32_t(storage_), pointee}));
            builtin_[cull] = m_.newId();
            g.push_back(make(spv::OpVariable, {pointer, builtin_[cull], std::uint32_t(storage_)}));
        }
        elementPointer_ = m_.newId();
        g.push_back(make(spv::OpTypePointer, {elementPointer_, std::uint32_t(storage_), floatType_}));
        for (const Distance& d : distances_) {
            for (std::uint32_t k = 0; k < std::max(d.vertices, d.first + d.components); ++k) indexConstant(g, k);
            const std::uint32_t pointer = privatePointer(g, d.pointee);
            if (hull_) privatePointer(g, d.valueType);
            g.push_back(make(spv::OpVariable, {pointer, d.variable, spv::StorageClassPrivate}));
        }
        // The access chains into them point to Private storage too.
        std::set<std::uint32_t> shadowed;
        for (const Distance& d : distances_) shadowed.insert(d.variable);
        for (bool grew = true; grew;) {
            grew = false;
            for (const SpirvInstruction& in : m_.instructions)
                if ((in.opcode() == spv::OpAccessChain || in.opcode() == spv::OpInBoundsAccessChain) && shadowed.count(in.word(3)) &&
                    shadowed.insert(in.word(2)).second) {
                    privatePointer(g, pointers_[in.word(1)].second);
                    grew = true;
                }
        }
        return g;
    }

    // Inputs: the Private copies filled from the built-in (vertex by vertex, component by component).
    void copyIn(std::vector<SpirvInstruction>& out) {
        for (const Distance& d : distances_) {
            for (std::uint32_t v = 0; v < d.vertices; ++v) {
                std::vector<std::uint32_t> parts;
                std::uint32_t whole = 0;
                for (std::uint32_t c = 0; c < d.components; ++c) {
                    const std::uint32_t element = m_.newId(), value = m_.newId();
                    out.push_back(make(spv::OpAccessChain, {elementPointer_, element, builtin_.at(d.cull), index_.at(v), index_.at(d.first + c)}));
                    out.push_back(make(spv::OpLoad, {floatType_, value, element}));
                    parts.push_back(value);
                    if (c == 0) whole = value;
                }
                if (d.components > 1) {
                    whole = m_.newId();
                    std::vector<std::uint32_t> words{spirvFirstWord(spv::OpCompositeConstruct, 3 + parts.size()), d.valueType, whole};
                    words.insert(words.end(), parts.begin(), parts.end());
                    out.push_back({std::move(words)});
                }
                const std::uint32_t slot = m_.newId();
                out.push_back(make(spv::OpAccessChain, {privatePointer_.at(d.valueType), slot, d.variable, index_.at(v)}));
                out.push_back(make(spv::OpStore, {slot, whole}));
            }
        }
    }

    // Outputs: the Private copies stored into the built-in.
    void copyOut(std::vector<SpirvInstruction>& out) {
        for (const Distance& d : distances_) {
            const std::uint32_t whole = m_.newId();
            out.push_back(make(spv::OpLoad, {d.valueType, whole, d.variable}));
            for (std::uint32_t c = 0; c < d.components; ++c) {
                std::uint32_t value = whole;
                if (d.components > 1) {
                    value = m_.newId();
                    out.push_back(make(spv::OpCompositeExtract, {floatType_, value, whole, c}));
                }
                const std::uint32_t element = m_.newId();
                out.push_back(make(spv::OpAccessChain, {elementPointer_, element, builtin_.at(d.cull), index_.at(d.first + c)}));
                out.push_back(make(spv::OpStore, {element, value}));
            }
        }
    }

    void edit(std::vector<SpirvInstruction> globals) {
        std::set<std::uint32_t> shadowed;  // the variables and the access chains into them
        for (const Distance& d : distances_) shadowed.insert(d.variable);
        bool annotated = false, declared = false, inEntry = false, entered = false;
        size_t annotationsLeft = 0;
        for (const SpirvInstruction& in : m_.instructions) annotationsLeft += isAnnotation(in.opcode()) ? 1 : 0;
        m_.rewrite([&](const SpirvInstruction& in, std::vector<SpirvInstruction>& out) {
            const std::uint32_t op = in.opcode();
            if (isAnnotation(op) && annotationsLeft > 0) --annotationsLeft;
            if (op == spv::OpEntryPoint) {
                // The interface lists the built-ins instead of the varyings.
                SpirvInstruction e = in;
                const size_t nameWords = spirvLiteralWords(spirvLiteralString(in, 3)).size();
                std::vector<std::uint32_t> words(in.words.begin(), in.words.begin() + std::ptrdiff_t(3 + nameWords));
                for (size_t k = 3 + nameWords; k < in.words.size(); ++k)
                    if (!shadowed.count(in.words[k])) words.push_back(in.words[k]);
                for (const auto& [cull, variable] : builtin_) words.push_back(variable);
                words[0] = spirvFirstWord(spv::OpEntryPoint, words.size());
                out.push_back({std::move(words)});
                return;
            }
            if ((op == spv::OpDecorate || op == spv::OpDecorateString) && shadowed.count(in.word(1))) {
                // A Private variable has no location or semantic.
            } else if (op == spv::OpVariable && shadowed.count(in.word(2))) {
                // Declared again, Private, after its new pointer type.
            } else if (op == spv::OpFunction && !declared) {
                out.insert(out.end(), globals.begin(), globals.end());
                declared = true;
                out.push_back(in);
            } else if (op == spv::OpAccessChain || op == spv::OpInBoundsAccessChain) {
                SpirvInstruction chain = in;
                if (shadowed.count(in.word(3))) {
                    chain.words[1] = privatePointer_.at(pointers_[in.word(1)].second);
                    shadowed.insert(in.word(2));
                }
                out.push_back(std::move(chain));
            } else if (op == spv::OpReturn && inEntry && !hull_) {
                copyOut(out);
                out.push_back(in);
            } else {
                if (inEntry && hull_ && !entered && op != spv::OpVariable && op != spv::OpLabel) {
                    copyIn(out);
                    entered = true;
                }
                out.push_back(in);
            }
            if (isAnnotation(op) && annotationsLeft == 0 && !annotated) {
                for (const auto& [cull, variable] : builtin_)
                    out.push_back(make(spv::OpDecorate, {variable, spv::DecorationBuiltIn,
                                                         std::uint32_t(cull ? spv::BuiltInCullDistance : spv::BuiltInClipDistance)}));
                annotated = true;
            }
            if (op == spv::OpFunction) inEntry = in.word(2) == entryFunction_;
            if (op == spv::OpFunctionEnd) inEntry = false;
        });
    }
};

}  // namespace

bool tessellationClipDistances(ParsedSpirv& m) { return Converter(m).run(); }

}  // namespace fxport::xlate
