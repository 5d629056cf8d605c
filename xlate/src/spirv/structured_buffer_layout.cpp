// Structured buffers repacked to D3D's tight layout (structured_buffer_layout.h).
#include "spirv/structured_buffer_layout.h"

#include "spirv/parsed_spirv.h"

#include <map>
#include <optional>
#include <set>

#include <spirv_cross/spirv.hpp>

namespace fxport::xlate {

namespace {

std::uint32_t opWord(spv::Op op, std::size_t count) { return (std::uint32_t(count) << 16) | std::uint32_t(op); }

// Where an access into a repacked buffer points: the block, its element array, or `words` (+ the
// uint value `dynamic`, when not 0) words into element `element`, at a value of type `type`.
struct Place {
    int level = 0;  // 0: the block, 1: the element array, 2: inside one element
    std::uint32_t element = 0;
    std::uint32_t words = 0;
    std::uint32_t dynamic = 0;
    std::uint32_t type = 0;
    bool rowMajor = false;              // `type` a matrix (or an array of them) whose SPIR-V columns are strided
    std::uint32_t componentStride = 1;  // `type` a vector: words between its components (a row-major column)
};

// A buffer to repack: its variable and the new types its words get.
struct Buffer {
    std::uint32_t variable = 0, storage = 0, oldBlock = 0, element = 0;  // element: T of T[]
    bool elementRowMajor = false;
    std::uint32_t strideWords = 0, oldStride = 0;  // D3D's stride in words, std430's in bytes
    std::uint32_t lengthConstant = 0, wordArray = 0, wordStruct = 0, runtimeArray = 0, block = 0, blockPointer = 0,
                  wordPointer = 0;
};

class Repacker {
public:
    explicit Repacker(ParsedSpirv& m) : m_(m) { scan(); }

    bool run() {
        findBuffers();
        if (buffers_.empty()) return false;
        if (!uint_) uint_ = m_.newId(), addUint_ = true;
        for (auto& [id, b] : buffers_) {
            b.lengthConstant = m_.newId();
            b.wordArray = m_.newId();
            b.wordStruct = m_.newId();
            b.runtimeArray = m_.newId();
            b.block = m_.newId();
            b.blockPointer = m_.newId();
            b.wordPointer = m_.newId();
        }
        bool decorated = false, declared = false;
        m_.rewrite([&](const SpirvInstruction& in, std::vector<SpirvInstruction>& out) {
            const spv::Op op = spv::Op(in.opcode());
            if (!decorated && (op == spv::OpDecorate || op == spv::OpMemberDecorate || op == spv::OpDecorationGroup)) {
                decorated = true;
                for (const auto& [id, b] : buffers_) decorate(b, out);
            }
            // A new uint goes before the first type; the new types and the variables (their old
            // declarations dropped) after every global, where the uint glslang declares late is known.
            if (addUint_ && op >= spv::OpTypeVoid && op <= spv::OpTypeForwardPointer) {
                out.push_back({{opWord(spv::OpTypeInt, 4), uint_, 32, 0}});
                addUint_ = false;
            }
            if (op == spv::OpVariable && buffers_.count(in.words[2])) return;
            if (op == spv::OpFunction && !declared) {
                declared = true;
                for (const auto& [id, b] : buffers_) declare(b, out);
            }
            rewriteUse(in, out);
        });
        return true;
    }

    // GetDimensions(count, stride): glslang stores its own (std430) stride, a constant, right after
    // the OpArrayLength of the count; it becomes D3D's. True when the module changed.
    bool strides() {
        const auto buffers = candidates();
        bool changed = false;
        auto& code = m_.instructions;
        for (std::size_t i = 0; i + 2 < code.size(); ++i) {
            const auto& w = code[i].words;
            if (code[i].opcode() != spv::OpArrayLength || w.size() < 5 || !buffers.count(w[3])) continue;
            const Buffer& b = buffers.at(w[3]);
            auto& count = code[i + 1].words;
            auto& stride = code[i + 2].words;
            if (code[i + 1].opcode() != spv::OpStore || count.size() < 3 || count[2] != w[2]) continue;
            if (code[i + 2].opcode() != spv::OpStore || stride.size() < 3) continue;
            auto constant = constants_.find(stride[2]);
            if (constant == constants_.end() || constant->second != b.oldStride) continue;
            stride[2] = m_.constant(m_.typeOf(stride[2]), 4 * b.strideWords);
            changed = true;
        }
        return changed;
    }

private:
    ParsedSpirv& m_;
    std::map<std::uint32_t, std::vector<std::uint32_t>> types_;
    std::map<std::uint32_t, std::uint32_t> constants_;
    std::map<std::uint32_t, std::vector<std::vector<std::uint32_t>>> decorations_;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::vector<std::uint32_t>>> memberDecorations_;
    std::uint32_t uint_ = 0;
    bool addUint_ = false;
    std::map<std::uint32_t, Buffer> buffers_;  // by variable
    std::map<std::uint32_t, Place> places_;    // pointer id -> where it points (for the rewrite)

    void scan() {
        for (const auto& in : m_.instructions) {
            const auto& w = in.words;
            const spv::Op op = spv::Op(in.opcode());
            if (op >= spv::OpTypeVoid && op <= spv::OpTypeForwardPointer && w.size() > 1) types_[w[1]] = w;
            if (op == spv::OpTypeInt && w.size() == 4 && w[2] == 32 && w[3] == 0) uint_ = w[1];
            if (op == spv::OpConstant && w.size() == 4) constants_[w[2]] = w[3];
            if (op == spv::OpDecorate && w.size() >= 3) decorations_[w[1]].push_back(w);
            if (op == spv::OpMemberDecorate && w.size() >= 4) memberDecorations_[{w[1], w[2]}].push_back(w);
        }
    }

    // The words of type `id`; for an unknown id, zeros (opcode 0, which is no type).
    const std::vector<std::uint32_t>& type(std::uint32_t id) const {
        static const std::vector<std::uint32_t> kNone(8, 0);
        auto it = types_.find(id);
        return it == types_.end() ? kNone : it->second;
    }
    std::optional<std::uint32_t> decoration(std::uint32_t id, spv::Decoration d) const {
        auto it = decorations_.find(id);
        if (it != decorations_.end())
            for (const auto& w : it->second)
                if (w[2] == d) return w.size() > 3 ? w[3] : 0;
        return std::nullopt;
    }
    std::optional<std::uint32_t> memberDecoration(std::uint32_t id, std::uint32_t member, spv::Decoration d) const {
        auto it = memberDecorations_.find({id, member});
        if (it != memberDecorations_.end())
            for (const auto& w : it->second)
                if (w[3] == d) return w.size() > 4 ? w[4] : 0;
        return std::nullopt;
    }
    std::uint32_t length(const std::vector<std::uint32_t>& array) const {
        auto it = constants_.find(array[3]);
        return it == constants_.end() ? 0 : it->second;
    }

    // D3D's size in words of a value of `id`; nullopt for what a structured buffer of words cannot
    // hold here (64-bit values, bools, opaque types).
    std::optional<std::uint32_t> tightWords(std::uint32_t id) const {
        const auto* t = &type(id);
        switch (spv::Op((*t)[0] & 0xFFFFu)) {
        case spv::OpTypeInt:
        case spv::OpTypeFloat:
            if ((*t)[2] != 32) return std::nullopt;
            return 1;
        case spv::OpTypeVector:
        case spv::OpTypeMatrix: {
            auto part = tightWords((*t)[2]);
            if (!part) return std::nullopt;
            return *part * (*t)[3];
        }
        case spv::OpTypeArray: {
            auto part = tightWords((*t)[2]);
            std::uint32_t n = length(*t);
            if (!part || n == 0) return std::nullopt;
            return *part * n;
        }
        case spv::OpTypeStruct: {
            std::uint32_t sum = 0;
            for (std::size_t i = 2; i < t->size(); ++i) {
                auto part = tightWords((*t)[i]);
                if (!part) return std::nullopt;
                sum += *part;
            }
            return sum;
        }
        default: return std::nullopt;
        }
    }
    std::uint32_t memberOffsetWords(std::uint32_t structId, std::uint32_t member) const {
        const auto& t = type(structId);
        std::uint32_t sum = 0;
        for (std::uint32_t i = 0; i < member; ++i) sum += *tightWords(t[2 + i]);
        return sum;
    }
    std::uint32_t opOf(std::uint32_t id) const {
        return type(id)[0] & 0xFFFFu;
    }
    // Words between two SPIR-V columns of a matrix, and between two components of one column.
    std::pair<std::uint32_t, std::uint32_t> matrixStrides(std::uint32_t matrix, bool rowMajor) const {
        const auto& t = type(matrix);
        const std::uint32_t rows = type(t[2])[3];
        return rowMajor ? std::pair<std::uint32_t, std::uint32_t>{1, t[3]} : std::pair<std::uint32_t, std::uint32_t>{rows, 1};
    }

    // Whether glslang's (std430) decorations of `id` already are D3D's tight layout.
    bool isTight(std::uint32_t id, bool rowMajor, std::optional<std::uint32_t> matrixStride) const {
        const auto* t = &type(id);
        switch (spv::Op((*t)[0] & 0xFFFFu)) {
        case spv::OpTypeMatrix: {
            // MatrixStride is the step between SPIR-V columns (column-major) or between rows.
            auto [column, component] = matrixStrides(id, rowMajor);
            return matrixStride == 4 * (rowMajor ? component : column);
        }
        case spv::OpTypeArray:
            return decoration(id, spv::DecorationArrayStride) == 4 * *tightWords((*t)[2]) && isTight((*t)[2], rowMajor, matrixStride);
        case spv::OpTypeStruct:
            for (std::uint32_t i = 0; i + 2 < t->size(); ++i) {
                if (memberDecoration(id, i, spv::DecorationOffset) != 4 * memberOffsetWords(id, i)) return false;
                if (!isTight((*t)[2 + i], memberDecoration(id, i, spv::DecorationRowMajor).has_value(),
                             memberDecoration(id, i, spv::DecorationMatrixStride)))
                    return false;
            }
            return true;
        default: return true;
        }
    }

    // The structured buffers whose std430 layout is not D3D's, by variable.
    std::map<std::uint32_t, Buffer> candidates() const {
        bool inFunctions = false;
        std::map<std::uint32_t, Buffer> candidates;
        for (const auto& in : m_.instructions) {
            const auto& w = in.words;
            if (in.opcode() == spv::OpFunction) inFunctions = true;
            if (inFunctions || in.opcode() != spv::OpVariable || w.size() < 4) continue;
            const auto* pointer = &type(w[1]);
            if (opOf(w[1]) != spv::OpTypePointer) continue;
            const std::uint32_t storage = (*pointer)[2], block = (*pointer)[3];
            if (storage != spv::StorageClassUniform && storage != spv::StorageClassStorageBuffer) continue;
            const auto* s = &type(block);
            if (opOf(block) != spv::OpTypeStruct || s->size() != 3 || opOf((*s)[2]) != spv::OpTypeRuntimeArray) continue;
            if (!decoration(block, spv::DecorationBufferBlock) && !(storage == spv::StorageClassStorageBuffer && decoration(block, spv::DecorationBlock)))
                continue;
            const std::uint32_t runtimeArray = (*s)[2];
            Buffer b;
            b.variable = w[2];
            b.storage = storage;
            b.oldBlock = block;
            b.element = type(runtimeArray)[2];
            b.elementRowMajor = memberDecoration(block, 0, spv::DecorationRowMajor).has_value();
            auto words = tightWords(b.element);
            if (!words || *words == 0) continue;
            b.strideWords = *words;
            b.oldStride = decoration(runtimeArray, spv::DecorationArrayStride).value_or(0);
            if (b.oldStride == 4 * *words &&
                isTight(b.element, b.elementRowMajor, memberDecoration(block, 0, spv::DecorationMatrixStride)))
                continue;  // std430 is D3D's layout here
            candidates[b.variable] = b;
        }
        return candidates;
    }

    void findBuffers() {
        for (auto& [id, b] : candidates())
            if (usesAreKnown(b)) buffers_[id] = b;
    }

    // Follows `indices` from `p`; with `out`, emits the word arithmetic (without, plans only).
    bool walk(Place& p, const std::uint32_t* indices, std::size_t count, std::vector<SpirvInstruction>* out) {
        for (std::size_t k = 0; k < count; ++k) {
            const std::uint32_t index = indices[k];
            auto constant = constants_.find(index);
            if (p.level == 0) {
                if (constant == constants_.end() || constant->second != 0) return false;
                p.level = 1;
                continue;
            }
            if (p.level == 1) {
                p.level = 2;
                p.element = index;
                continue;
            }
            const auto* t = &type(p.type);
            std::uint32_t scale = 0, next = 0, stride = 1;
            switch (spv::Op((*t)[0] & 0xFFFFu)) {
            case spv::OpTypeStruct: {
                if (constant == constants_.end() || constant->second + 2 >= t->size()) return false;
                const std::uint32_t member = constant->second;
                p.words += memberOffsetWords(p.type, member);
                p.rowMajor = memberDecoration(p.type, member, spv::DecorationRowMajor).has_value();
                p.type = (*t)[2 + member];
                p.componentStride = 1;
                continue;
            }
            case spv::OpTypeArray: scale = *tightWords((*t)[2]), next = (*t)[2]; break;
            case spv::OpTypeMatrix: {
                auto [column, component] = matrixStrides(p.type, p.rowMajor);
                scale = column, next = (*t)[2], stride = component;
                break;
            }
            case spv::OpTypeVector: scale = p.componentStride, next = (*t)[2]; break;
            default: return false;
            }
            if (constant != constants_.end()) p.words += constant->second * scale;
            else if (!out) p.dynamic = 1;
            else p.dynamic = addDynamic(p.dynamic, index, scale, *out);
            p.type = next;
            p.componentStride = stride;
        }
        return true;
    }

    std::uint32_t addDynamic(std::uint32_t sum, std::uint32_t index, std::uint32_t scale, std::vector<SpirvInstruction>& out) {
        std::uint32_t value = index;
        if (m_.typeOf(index) != uint_) {
            out.push_back(m_.value(spv::OpBitcast, uint_, {index}));
            value = out.back().words[2];
        }
        if (scale != 1) {
            out.push_back(m_.value(spv::OpIMul, uint_, {value, m_.constant(uint_, scale)}));
            value = out.back().words[2];
        }
        if (!sum) return value;
        out.push_back(m_.value(spv::OpIAdd, uint_, {sum, value}));
        return out.back().words[2];
    }

    // The variable's place: the block, with the element's type and majorness for what follows.
    static Place elementPlace(const Buffer& b) {
        Place p;
        p.type = b.element;
        p.rowMajor = b.elementRowMajor;
        return p;
    }

    bool isUintScalar(std::uint32_t id) const {
        const auto* t = &type(id);
        return opOf(id) == spv::OpTypeInt && (*t)[2] == 32 && (*t)[3] == 0;
    }

    // Every use of the buffer is an access, a load, a store, the array length or a uint atomic.
    bool usesAreKnown(const Buffer& b) {
        std::map<std::uint32_t, Place> places{{b.variable, elementPlace(b)}};
        bool inFunctions = false;
        for (const auto& in : m_.instructions) {
            const auto& w = in.words;
            const spv::Op op = spv::Op(in.opcode());
            if (op == spv::OpFunction) inFunctions = true;
            if (!inFunctions) continue;
            if ((op == spv::OpAccessChain || op == spv::OpInBoundsAccessChain) && w.size() > 3 && places.count(w[3])) {
                Place p = places.at(w[3]);
                if (!walk(p, w.data() + 4, w.size() - 4, nullptr)) return false;
                places[w[2]] = p;
                continue;
            }
            for (std::size_t k = 1; k < w.size(); ++k) {
                auto it = places.find(w[k]);
                if (it == places.end()) continue;
                const Place& p = it->second;
                const bool atomic = op >= spv::OpAtomicLoad && op <= spv::OpAtomicXor;
                const std::size_t pointerAt = op == spv::OpStore || op == spv::OpAtomicStore ? 1 : 3;
                if (k == pointerAt && p.level == 2 && (op == spv::OpLoad || op == spv::OpStore)) continue;
                if (k == pointerAt && p.level == 2 && atomic && isUintScalar(p.type)) continue;
                if (k == 3 && op == spv::OpArrayLength && p.level == 0) continue;
                return false;
            }
        }
        return true;
    }

    // The new types of `b` and its variable (the same id) of the new type.
    void declare(const Buffer& b, std::vector<SpirvInstruction>& out) {
        out.push_back({{opWord(spv::OpConstant, 4), uint_, b.lengthConstant, b.strideWords}});
        out.push_back({{opWord(spv::OpTypeArray, 4), b.wordArray, uint_, b.lengthConstant}});
        out.push_back({{opWord(spv::OpTypeStruct, 3), b.wordStruct, b.wordArray}});
        out.push_back({{opWord(spv::OpTypeRuntimeArray, 3), b.runtimeArray, b.wordStruct}});
        out.push_back({{opWord(spv::OpTypeStruct, 3), b.block, b.runtimeArray}});
        out.push_back({{opWord(spv::OpTypePointer, 4), b.blockPointer, b.storage, b.block}});
        out.push_back({{opWord(spv::OpTypePointer, 4), b.wordPointer, b.storage, uint_}});
        out.push_back({{opWord(spv::OpVariable, 4), b.blockPointer, b.variable, b.storage}});
    }

    void decorate(const Buffer& b, std::vector<SpirvInstruction>& out) {
        out.push_back({{opWord(spv::OpDecorate, 4), b.wordArray, spv::DecorationArrayStride, 4}});
        out.push_back({{opWord(spv::OpMemberDecorate, 5), b.wordStruct, 0, spv::DecorationOffset, 0}});
        out.push_back({{opWord(spv::OpDecorate, 4), b.runtimeArray, spv::DecorationArrayStride, 4 * b.strideWords}});
        out.push_back({{opWord(spv::OpMemberDecorate, 5), b.block, 0, spv::DecorationOffset, 0}});
        if (auto it = decorations_.find(b.oldBlock); it != decorations_.end())
            for (auto w : it->second) {
                w[1] = b.block;
                out.push_back({std::move(w)});
            }
        if (auto it = memberDecorations_.find({b.oldBlock, 0}); it != memberDecorations_.end())
            for (auto w : it->second) {
                const std::uint32_t d = w[3];
                if (d == spv::DecorationOffset || d == spv::DecorationMatrixStride || d == spv::DecorationRowMajor ||
                    d == spv::DecorationColMajor)
                    continue;
                w[1] = b.block;
                out.push_back({std::move(w)});
            }
    }

    std::uint32_t wordPointer(const Buffer& b, const Place& p, std::vector<SpirvInstruction>& out) {
        std::uint32_t offset = m_.constant(uint_, p.words);
        if (p.dynamic) {
            if (p.words == 0) offset = p.dynamic;
            else {
                out.push_back(m_.value(spv::OpIAdd, uint_, {p.dynamic, offset}));
                offset = out.back().words[2];
            }
        }
        const std::uint32_t zero = m_.constant(uint_, 0);
        out.push_back(m_.value(spv::OpAccessChain, b.wordPointer, {b.variable, zero, p.element, zero, offset}));
        return out.back().words[2];
    }

    // The parts of a composite at `p`: each part's place (type set) in order.
    std::vector<Place> parts(const Place& p) const {
        const auto& t = type(p.type);
        std::vector<Place> out;
        auto add = [&](std::uint32_t partType, std::uint32_t words, bool rowMajor, std::uint32_t componentStride) {
            Place q = p;
            q.type = partType, q.words = p.words + words, q.rowMajor = rowMajor, q.componentStride = componentStride;
            out.push_back(q);
        };
        switch (spv::Op(t[0] & 0xFFFFu)) {
        case spv::OpTypeVector:
            for (std::uint32_t i = 0; i < t[3]; ++i) add(t[2], i * p.componentStride, false, 1);
            break;
        case spv::OpTypeMatrix: {
            auto [column, component] = matrixStrides(p.type, p.rowMajor);
            for (std::uint32_t i = 0; i < t[3]; ++i) add(t[2], i * column, false, component);
            break;
        }
        case spv::OpTypeArray:
            for (std::uint32_t i = 0, n = length(t), w = *tightWords(t[2]); i < n; ++i) add(t[2], i * w, p.rowMajor, 1);
            break;
        case spv::OpTypeStruct:
            for (std::uint32_t i = 0; i + 2 < t.size(); ++i)
                add(t[2 + i], memberOffsetWords(p.type, i), memberDecoration(p.type, i, spv::DecorationRowMajor).has_value(), 1);
            break;
        default: break;
        }
        return out;
    }

    std::uint32_t load(const Buffer& b, const Place& p, std::vector<SpirvInstruction>& out) {
        const std::uint32_t op = opOf(p.type);
        if (op == spv::OpTypeInt || op == spv::OpTypeFloat) {
            out.push_back(m_.value(spv::OpLoad, uint_, {wordPointer(b, p, out)}));
            if (p.type == uint_) return out.back().words[2];
            out.push_back(m_.value(spv::OpBitcast, p.type, {out.back().words[2]}));
            return out.back().words[2];
        }
        std::vector<std::uint32_t> values;
        for (const Place& q : parts(p)) values.push_back(load(b, q, out));
        out.push_back(m_.value(spv::OpCompositeConstruct, p.type, values));
        return out.back().words[2];
    }

    void store(const Buffer& b, const Place& p, std::uint32_t value, std::vector<SpirvInstruction>& out) {
        const std::uint32_t op = opOf(p.type);
        if (op == spv::OpTypeInt || op == spv::OpTypeFloat) {
            if (p.type != uint_) {
                out.push_back(m_.value(spv::OpBitcast, uint_, {value}));
                value = out.back().words[2];
            }
            const std::uint32_t pointer = wordPointer(b, p, out);
            out.push_back({{opWord(spv::OpStore, 3), pointer, value}});
            return;
        }
        std::uint32_t i = 0;
        for (const Place& q : parts(p)) {
            out.push_back(m_.value(spv::OpCompositeExtract, q.type, {value, i++}));
            store(b, q, out.back().words[2], out);
        }
    }

    void rewriteUse(const SpirvInstruction& in, std::vector<SpirvInstruction>& out) {
        const auto& w = in.words;
        const spv::Op op = spv::Op(in.opcode());
        if ((op == spv::OpAccessChain || op == spv::OpInBoundsAccessChain) && w.size() > 3) {
            const Place* base = placeOf(w[3]);
            if (base) {
                Place p = *base;
                walk(p, w.data() + 4, w.size() - 4, &out);
                places_[w[2]] = p;
                owner_[w[2]] = owner_.at(w[3]);
                return;
            }
        }
        if (op == spv::OpLoad && w.size() > 3 && placeOf(w[3])) {
            const std::uint32_t value = load(buffer(w[3]), *placeOf(w[3]), out);
            out.push_back({{opWord(spv::OpCopyObject, 4), w[1], w[2], value}});
            return;
        }
        if (op == spv::OpStore && w.size() > 2 && placeOf(w[1])) return store(buffer(w[1]), *placeOf(w[1]), w[2], out);
        const bool atomic = op >= spv::OpAtomicLoad && op <= spv::OpAtomicXor;
        const std::size_t pointerAt = op == spv::OpAtomicStore ? 1 : 3;
        if (atomic && w.size() > pointerAt && placeOf(w[pointerAt]) && placeOf(w[pointerAt])->level == 2) {
            SpirvInstruction copy = in;
            copy.words[pointerAt] = wordPointer(buffer(w[pointerAt]), *placeOf(w[pointerAt]), out);
            out.push_back(std::move(copy));
            return;
        }
        out.push_back(in);
    }

    std::map<std::uint32_t, std::uint32_t> owner_;  // pointer id -> buffer variable
    const Place* placeOf(std::uint32_t id) {
        if (buffers_.count(id) && !places_.count(id)) {
            places_[id] = elementPlace(buffers_.at(id));
            owner_[id] = id;
        }
        auto it = places_.find(id);
        return it == places_.end() ? nullptr : &it->second;
    }
    const Buffer& buffer(std::uint32_t pointer) const { return buffers_.at(owner_.at(pointer)); }
};

}  // namespace

bool structuredBufferStridesAsD3D(ParsedSpirv& m) {
    Repacker repacker(m);
    return repacker.strides();
}

bool packStructuredBuffersTightly(ParsedSpirv& m) {
    Repacker repacker(m);
    return repacker.run();
}

}  // namespace fxport::xlate
