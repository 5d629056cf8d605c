// See out_of_range_accesses.h.
#include "spirv/out_of_range_accesses.h"

#include <map>
#include <set>
#include <vector>

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kCapability = 17, kTypeImage = 25, kTypeRuntimeArray = 29, kTypeStruct = 30, kTypePointer = 32,
                        kVariable = 59, kLoad = 61, kAccessChain = 65, kInBoundsAccessChain = 66, kArrayLength = 68,
                        kCompositeConstruct = 80, kCompositeExtract = 81, kImageFetch = 95, kImageRead = 98,
                        kImageQuerySizeLod = 103, kImageQuerySize = 104, kImageQueryLevels = 106,
                        kImageQuerySamples = 107, kIAdd = 128, kLogicalAnd = 167, kSelect = 169, kULessThan = 176;
constexpr std::uint32_t kStore = 62, kAtomicLoad = 227, kAtomicStore = 228, kAtomicXor = 242, kPhi = 245, kLoopMerge = 246,
                        kSelectionMerge = 247, kLabel = 248, kBranch = 249, kBranchConditional = 250;
constexpr std::uint32_t kImageQueryCapability = 50, kDimBuffer = 5;
constexpr std::uint32_t kUniform = 2, kStorageBuffer = 12;
constexpr std::uint32_t kLod = 0x2, kConstOffset = 0x8, kSample = 0x40;

// The word index of image operand `bit` of an instruction whose mask is at word 5, 0 when absent.
size_t imageOperand(const SpirvInstruction& in, std::uint32_t bit) {
    const std::uint32_t mask = in.word(5);
    if (in.words.size() < 7 || !(mask & bit)) return 0;
    size_t at = 6;
    for (std::uint32_t b = 1; b < bit; b <<= 1)
        if (mask & b) at += (b == 0x4) ? 2 : 1;  // Grad takes two ids, every other operand one
    return at < in.words.size() ? at : 0;
}

// Whether `id` is a constant scalar or vector of zeros.
bool isConstantZero(const ParsedSpirv& m, std::uint32_t id) {
    const SpirvInstruction* d = m.definition(id);
    if (d && d->opcode() == spv_op::ConstantComposite) {
        for (size_t k = 3; k < d->words.size(); ++k)
            if (!isConstantZero(m, d->words[k])) return false;
        return true;
    }
    return d && (d->opcode() == spv_op::ConstantNull || (d->opcode() == spv_op::Constant && d->word(3) == 0));
}

// Whether the texel read `in` reads texel 0 (slice 0, level 0, sample 0), which every texture has.
bool readsFirstTexel(const ParsedSpirv& m, const SpirvInstruction& in) {
    for (std::uint32_t bit : {kLod, kConstOffset, kSample})
        if (size_t at = imageOperand(in, bit); at && !isConstantZero(m, in.words[at])) return false;
    return isConstantZero(m, in.words[4]);
}

struct Emitter {
    ParsedSpirv& m;
    std::vector<SpirvInstruction>& out;
    std::uint32_t boolType = m.boolTypeLike(0);

    std::uint32_t emit(std::uint32_t opcode, std::uint32_t type, const std::vector<std::uint32_t>& operands) {
        out.push_back(m.value(opcode, type, operands));
        return out.back().words[2];
    }
    // Unsigned a < b (a negative int is out of range too), all components, as one bool.
    std::uint32_t below(std::uint32_t a, std::uint32_t b) {
        const std::uint32_t count = m.components(m.typeOf(a)).second;
        std::uint32_t less = emit(kULessThan, m.boolTypeLike(m.typeOf(a)), {a, b});
        return count == 1 ? less : emit(spv_op::All, boolType, {less});
    }
    std::uint32_t both(std::uint32_t a, std::uint32_t b) { return a ? emit(kLogicalAnd, boolType, {a, b}) : b; }
    // `%result = ok ? value : 0` of a scalar or vector type.
    SpirvInstruction select(std::uint32_t type, std::uint32_t result, std::uint32_t ok, std::uint32_t value) {
        const std::uint32_t count = m.components(type).second;
        if (count > 1) ok = emit(kCompositeConstruct, m.boolTypeLike(type), std::vector<std::uint32_t>(count, ok));
        return {{spirvFirstWord(kSelect, 6), type, result, ok, value, m.splatConstant(type, 0)}};
    }
    // `coordinate + offset`, the offset widened with zeros to the coordinate's components (an
    // array's layer is not offset).
    std::uint32_t offset(std::uint32_t coordinate, std::uint32_t offset) {
        const std::uint32_t type = m.typeOf(coordinate);
        auto [scalar, count] = m.components(type);
        const std::uint32_t offsetCount = m.components(m.typeOf(offset)).second;
        if (offsetCount > count) return coordinate;
        if (offsetCount < count) {
            std::vector<std::uint32_t> parts;
            for (std::uint32_t k = 0; k < count; ++k)
                parts.push_back(k >= offsetCount ? m.constant(scalar, 0) : offsetCount == 1 ? offset : emit(kCompositeExtract, scalar, {offset, k}));
            offset = emit(kCompositeConstruct, type, parts);
        }
        return emit(kIAdd, type, {coordinate, offset});
    }
};

// The texel read `in` (OpImageFetch or OpImageRead) as `inRange ? texel : 0`.
void guardTexelRead(ParsedSpirv& m, const SpirvInstruction& in, const SpirvInstruction& imageType, std::vector<SpirvInstruction>& out) {
    Emitter e{m, out};
    const std::uint32_t image = in.words[3];
    std::uint32_t coordinate = in.words[4];
    const std::uint32_t coordinateType = m.typeOf(coordinate);
    const bool multisampled = imageType.word(6) == 1, sampled = imageType.word(7) == 1;
    if (size_t at = imageOperand(in, kConstOffset)) coordinate = e.offset(coordinate, in.words[at]);
    const size_t lodAt = imageOperand(in, kLod), sampleAt = imageOperand(in, kSample);
    std::uint32_t ok = 0;
    std::uint32_t size = 0;
    if (in.opcode() == kImageFetch && sampled && !multisampled && imageType.word(3) != kDimBuffer) {
        const std::uint32_t lod = lodAt ? in.words[lodAt] : m.constant(m.intType(), 0);
        size = e.emit(kImageQuerySizeLod, coordinateType, {image, lod});
        if (lodAt && !isConstantZero(m, lod)) ok = e.below(lod, e.emit(kImageQueryLevels, m.typeOf(lod), {image}));
    } else {
        size = e.emit(kImageQuerySize, coordinateType, {image});
    }
    ok = e.both(ok, e.below(coordinate, size));
    if (multisampled && sampleAt)
        ok = e.both(ok, e.below(in.words[sampleAt], e.emit(kImageQuerySamples, m.typeOf(in.words[sampleAt]), {image})));
    SpirvInstruction read = in;
    read.words[2] = m.newId();
    out.push_back(read);
    out.push_back(e.select(in.words[1], in.words[2], ok, read.words[2]));
}

bool isScalarOrVector(const ParsedSpirv& m, std::uint32_t type) {
    const SpirvInstruction* t = m.definition(m.components(type).first);
    return t && (t->opcode() == spv_op::TypeInt || t->opcode() == spv_op::TypeFloat || t->opcode() == spv_op::TypeBool);
}

// Buffers ending in a runtime array (structured and byte-address buffers): variable -> the member.
std::map<std::uint32_t, std::uint32_t> runtimeArrayBuffers(const ParsedSpirv& m) {
    std::map<std::uint32_t, std::uint32_t> out;
    for (const SpirvInstruction& in : m.instructions) {
        if (in.opcode() != kVariable || (in.word(3) != kUniform && in.word(3) != kStorageBuffer)) continue;
        const SpirvInstruction* pointer = m.definition(in.words[1]);
        const SpirvInstruction* block = pointer && pointer->opcode() == kTypePointer ? m.definition(pointer->word(3)) : nullptr;
        if (!block || block->opcode() != kTypeStruct || block->words.size() < 3) continue;
        const SpirvInstruction* last = m.definition(block->words.back());
        if (last && last->opcode() == kTypeRuntimeArray) out[in.words[2]] = std::uint32_t(block->words.size() - 3);
    }
    return out;
}

// The access chains `pointer` is made of when it points into the runtime array of one of
// `buffers`: `pointer`'s chain first, then each chain its base is, the last one on the buffer itself
// (base, the member's constant, then the element's index); none when it points elsewhere.
std::vector<const SpirvInstruction*> elementChains(const ParsedSpirv& m, const std::map<std::uint32_t, std::uint32_t>& buffers,
                                                   std::uint32_t pointer) {
    std::vector<const SpirvInstruction*> chains;
    for (const SpirvInstruction* chain = m.definition(pointer);
         chain && (chain->opcode() == kAccessChain || chain->opcode() == kInBoundsAccessChain) && chain->words.size() >= 5 && chains.size() < 8;
         chain = m.definition(chain->words[3])) {
        chains.push_back(chain);
        auto member = buffers.find(chain->words[3]);
        if (member == buffers.end()) continue;
        const SpirvInstruction* first = m.definition(chain->words[4]);
        if (chain->words.size() < 6 || !first || first->opcode() != spv_op::Constant || first->word(3) != member->second) break;
        return chains;
    }
    return {};
}

}  // namespace

// Tests: xlate OutOfRangeReads.*; d3d11 D3D11OutOfRangeReads.*.
bool outOfRangeReadsReadZero(ParsedSpirv& m) {
    if (!m.has({kImageFetch, kImageRead, kArrayLength, kAccessChain, kInBoundsAccessChain})) return false;
    const std::map<std::uint32_t, std::uint32_t> runtimeArrayMember = runtimeArrayBuffers(m);
    bool hasImageQuery = false;
    for (const SpirvInstruction& in : m.instructions)
        if (in.opcode() == kCapability && in.word(1) == kImageQueryCapability) hasImageQuery = true;
    bool changed = false, capabilityAdded = hasImageQuery || !m.has({kImageFetch, kImageRead});
    m.rewrite([&](const SpirvInstruction& in, std::vector<SpirvInstruction>& out) {
        if (in.opcode() == kCapability && !capabilityAdded) {  // texel guards query sizes
            out.push_back(in);
            out.push_back({{spirvFirstWord(kCapability, 2), kImageQueryCapability}});
            capabilityAdded = changed = true;
            return;
        }
        if ((in.opcode() == kImageFetch || in.opcode() == kImageRead) && in.words.size() >= 5) {
            const SpirvInstruction* imageType = m.definition(m.typeOf(in.words[3]));
            if (!imageType || imageType->opcode() != kTypeImage || !isScalarOrVector(m, in.words[1]) || readsFirstTexel(m, in))
                return out.push_back(in);
            guardTexelRead(m, in, *imageType, out);
            changed = true;
            return;
        }
        if (in.opcode() != kLoad || in.words.size() < 4 || !isScalarOrVector(m, in.words[1])) return out.push_back(in);
        const std::vector<const SpirvInstruction*> chains = elementChains(m, runtimeArrayMember, in.words[3]);
        if (chains.empty()) return out.push_back(in);
        const SpirvInstruction& element = *chains.back();
        // index < length; the load reads through a clamped index, so that it stays inside the buffer.
        Emitter e{m, out};
        const std::uint32_t index = element.words[5], indexType = m.typeOf(index);
        const std::uint32_t length = e.emit(kArrayLength, m.uintType(), {element.words[3], runtimeArrayMember.at(element.words[3])});
        const std::uint32_t ok = e.emit(kULessThan, e.boolType, {index, length});
        std::uint32_t safe = e.emit(kSelect, indexType, {ok, index, m.constant(indexType, 0)});
        for (auto c = chains.rbegin(); c != chains.rend(); ++c) {  // the chains again, from the buffer out
            SpirvInstruction copy = **c;
            copy.words[2] = m.newId();
            copy.words[c == chains.rbegin() ? 5 : 3] = safe;
            out.push_back(copy);
            safe = copy.words[2];
        }
        SpirvInstruction load = in;
        load.words[2] = m.newId();
        load.words[3] = safe;
        out.push_back(load);
        out.push_back(e.select(in.words[1], in.words[2], ok, load.words[2]));
        changed = true;
    });
    return changed;
}

// Tests: xlate OutOfRangeReads.BufferWritesAndAtomicsRunOnlyInsideTheBuffer,
// OutOfRangeReads.AccessesInLoopHeadersAreGuarded; d3d11 D3D11OutOfRangeReads.BufferWritesPastTheViewAreDropped.
bool outOfRangeBufferWritesDropped(ParsedSpirv& m) {
    if (!m.has({kStore, kAtomicStore, kLoad}) && !m.has({229, 230, 231, 232, 233, 234, 235, 236, 237, 238, 239, 240, 241, kAtomicXor}))
        return false;
    const std::map<std::uint32_t, std::uint32_t> buffers = runtimeArrayBuffers(m);
    if (buffers.empty()) return false;
    // The chains of an access to guard (a store, an atomic, or a load of a struct, matrix or array,
    // which OpSelect cannot choose on SPIR-V 1.0), none for any other instruction.
    auto guarded = [&](const SpirvInstruction& in) -> std::vector<const SpirvInstruction*> {
        const bool store = in.opcode() == kStore || in.opcode() == kAtomicStore;
        const bool valued = (in.opcode() >= kAtomicLoad && in.opcode() <= kAtomicXor && in.opcode() != kAtomicStore) ||
                            (in.opcode() == kLoad && in.words.size() >= 4 && !isScalarOrVector(m, in.words[1]));
        const size_t pointerAt = store ? 1 : 3;
        if ((!store && !valued) || in.words.size() <= pointerAt) return {};
        return elementChains(m, buffers, in.words[pointerAt]);
    };
    // A loop header with such an access is split first: its phis and merge instruction stay (its back
    // edges name it), and a branch leads to a new block with the rest, which is split like any other.
    std::map<std::uint32_t, SpirvInstruction> loopMerges;  // header -> its OpLoopMerge
    std::set<std::uint32_t> accessBlocks;
    std::uint32_t label = 0;
    for (const SpirvInstruction& in : m.instructions) {
        if (in.opcode() == kLabel) label = in.word(1);
        if (in.opcode() == kLoopMerge) loopMerges[label] = in;
        if (!guarded(in).empty()) accessBlocks.insert(label);
    }
    // The block each split block's terminator ended in (a phi naming the block names that one now),
    // and the phis the pass adds (which name the split parts themselves).
    std::map<std::uint32_t, std::uint32_t> endsIn;
    std::set<std::uint32_t> newPhis;
    std::uint32_t block = 0;      // the block the instruction is in: `label` or the last part split from it
    bool headerPrologue = false;  // in a loop header to split, before its first instruction past the phis
    bool changed = false;
    m.rewrite([&](const SpirvInstruction& in, std::vector<SpirvInstruction>& out) {
        if (in.opcode() == kLabel) {
            label = block = in.word(1);
            headerPrologue = loopMerges.count(label) && accessBlocks.count(label);
            return out.push_back(in);
        }
        if (headerPrologue && in.opcode() != kPhi && in.opcode() != 8 && in.opcode() != 317) {  // OpLine, OpNoLine
            headerPrologue = false;
            SpirvInstruction merge = loopMerges.at(label);
            const std::uint32_t body = m.newId();
            if (merge.words[2] == label) merge.words[2] = body;  // a header that was its own continue target
            out.push_back(merge);
            out.push_back({{spirvFirstWord(kBranch, 2), body}});
            out.push_back({{spirvFirstWord(kLabel, 2), body}});
            endsIn[label] = block = body;
            changed = true;
        }
        if (in.opcode() == kLoopMerge && endsIn.count(label)) return;  // placed above
        const std::vector<const SpirvInstruction*> chains = guarded(in);
        if (chains.empty() || loopMerges.count(block)) return out.push_back(in);
        const SpirvInstruction& element = *chains.back();
        // if (index < length) { the access } -- an atomic's or a composite's value is 0 when skipped.
        Emitter e{m, out};
        const std::uint32_t length = e.emit(kArrayLength, m.uintType(), {element.words[3], buffers.at(element.words[3])});
        const std::uint32_t ok = e.emit(kULessThan, e.boolType, {element.words[5], length});
        const std::uint32_t then = m.newId(), merge = m.newId();
        out.push_back({{spirvFirstWord(kSelectionMerge, 3), merge, 0}});
        out.push_back({{spirvFirstWord(kBranchConditional, 4), ok, then, merge}});
        out.push_back({{spirvFirstWord(kLabel, 2), then}});
        SpirvInstruction access = in;
        const bool valued = in.opcode() != kStore && in.opcode() != kAtomicStore;
        if (valued) access.words[2] = m.newId();
        out.push_back(access);
        out.push_back({{spirvFirstWord(kBranch, 2), merge}});
        out.push_back({{spirvFirstWord(kLabel, 2), merge}});
        if (valued) {
            out.push_back({{spirvFirstWord(kPhi, 7), in.words[1], in.words[2], access.words[2], then, m.splatConstant(in.words[1], 0), block}});
            newPhis.insert(in.words[2]);
        }
        endsIn[label] = block = merge;
        changed = true;
    });
    if (!changed) return false;
    for (SpirvInstruction& in : m.instructions) {
        if (in.opcode() != kPhi || newPhis.count(in.word(2))) continue;
        for (size_t k = 4; k < in.words.size(); k += 2)
            if (auto it = endsIn.find(in.words[k]); it != endsIn.end()) in.words[k] = it->second;
    }
    return true;
}

}  // namespace fxport::xlate
