// D3D's cbuffer packing on glslang's SPIR-V, and the register-array form of a block GLSL cannot
// declare at those offsets (cbuffer_packing.h).
#include "spirv/cbuffer_packing.h"

#include <algorithm>
#include <map>
#include <set>

#include "fx/fx_syntax.h"
#include "rewrite/uniform_object_structs.h"
#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

namespace {

// Opcodes and decorations (spirv.hpp numbers; SPIRV-Cross's header is not included here).
enum : std::uint32_t {
    kOpName = 5, kOpMemberName = 6, kOpTypeBool = 20, kOpTypeInt = 21, kOpTypeFloat = 22, kOpTypeVector = 23,
    kOpTypeMatrix = 24, kOpTypeArray = 28, kOpTypeStruct = 30, kOpTypePointer = 32, kOpConstant = 43,
    kOpFunction = 54, kOpVariable = 59, kOpLoad = 61, kOpAccessChain = 65, kOpInBoundsAccessChain = 66,
    kOpDecorate = 71, kOpMemberDecorate = 72, kOpVectorExtractDynamic = 77, kOpCompositeConstruct = 80,
    kOpCompositeExtract = 81, kOpBitcast = 124, kOpIAdd = 128, kOpIMul = 132, kOpINotEqual = 171,
};
enum : std::uint32_t { kDecBlock = 2, kDecRowMajor = 4, kDecArrayStride = 6, kDecMatrixStride = 7, kDecOffset = 35 };
constexpr std::uint32_t kStorageUniform = 2;

std::uint32_t roundUp16(std::uint32_t v) { return (v + 15) / 16 * 16; }

// One instruction as this file reads it: its index in the module, and the word indices (from
// its start) of the ids it uses.
struct Inst {
    std::size_t at = 0;
    std::uint32_t op = 0;
    std::uint32_t count = 0;
    std::uint32_t type = 0;
    std::uint32_t result = 0;
    std::vector<std::uint16_t> uses;
};

// The shared module (parsed_spirv.h), freshly parsed, with the look-ups the packing makes.
struct Module {
    explicit Module(ParsedSpirv& parsed) : spirv(parsed) {
        for (std::size_t k = 0; k < spirv.instructions.size(); ++k) {
            const SpirvInstructionIds& ids = spirv.ids(k);
            Inst i;
            i.at = k;
            i.op = spirv.instructions[k].opcode();
            i.count = std::uint32_t(spirv.instructions[k].words.size());
            i.type = ids.type;
            i.result = ids.result;
            i.uses = ids.operands;
            if (i.result) def[i.result] = insts.size();
            if (i.result && i.type) typeOf[i.result] = i.type;
            insts.push_back(std::move(i));
        }
    }
    ParsedSpirv& spirv;
    std::vector<Inst> insts;
    std::map<std::uint32_t, std::size_t> def;  // result id -> instruction index
    std::map<std::uint32_t, std::uint32_t> typeOf;

    std::uint32_t w(const Inst& i, std::uint32_t k) const { return k < i.count ? spirv.instructions[i.at].words[k] : 0; }
    const std::vector<std::uint32_t>& words(const Inst& i) const { return spirv.instructions[i.at].words; }
    // A word to overwrite: word k of instruction `index`.
    std::uint32_t& word(std::pair<std::size_t, std::uint32_t> at) { return spirv.instructions[at.first].words[at.second]; }
    const Inst* defOf(std::uint32_t id) const {
        auto it = def.find(id);
        return it == def.end() ? nullptr : &insts[it->second];
    }
    // The definition of `id`, or an empty instruction (op 0, no words) where there is none.
    const Inst& instOf(std::uint32_t id) const {
        static const Inst kNone;
        const Inst* i = defOf(id);
        return i ? *i : kNone;
    }
    std::string stringAt(const Inst& i, std::uint32_t k) const {
        std::string s;
        for (std::uint32_t j = k; j < i.count; ++j)
            for (int b = 0; b < 4; ++b) {
                char c = char((w(i, j) >> (8 * b)) & 0xFF);
                if (!c) return s;
                s += c;
            }
        return s;
    }
};

// D3D packing of the types a block reaches: member offsets and sizes, array strides.
class Packer {
public:
    explicit Packer(Module& m) : m_(m) {
        for (const Inst& i : m_.insts) {
            if (i.op == kOpMemberDecorate && m_.w(i, 3) == kDecRowMajor) rowMajor_.insert({m_.w(i, 1), m_.w(i, 2)});
            if (i.op == kOpMemberDecorate && m_.w(i, 3) == kDecOffset) offsetWord_[{m_.w(i, 1), m_.w(i, 2)}] = {i.at, 4};
            if (i.op == kOpMemberDecorate && m_.w(i, 3) == kDecMatrixStride) matrixStrideWord_[{m_.w(i, 1), m_.w(i, 2)}] = {i.at, 4};
            if (i.op == kOpDecorate && m_.w(i, 2) == kDecArrayStride) arrayStrideWord_[m_.w(i, 1)] = {i.at, 3};
        }
    }

    std::uint32_t constant(std::uint32_t id) const {
        const Inst* c = m_.defOf(id);
        return c && c->op == kOpConstant ? m_.w(*c, 3) : 0;
    }
    bool isConstant(std::uint32_t id) const {
        const Inst* c = m_.defOf(id);
        return c && c->op == kOpConstant;
    }
    const Inst* type(std::uint32_t id) const { return m_.defOf(id); }
    std::uint32_t memberType(std::uint32_t structId, std::uint32_t k) const { return m_.w(m_.instOf(structId), 2 + k); }
    std::uint32_t memberCount(std::uint32_t structId) const {
        const Inst& t = m_.instOf(structId);
        return t.count >= 2 ? t.count - 2 : 0;
    }
    bool memberRowMajor(std::uint32_t structId, std::uint32_t k) const { return rowMajor_.count({structId, k}) > 0; }

    // D3D size in bytes of a value of `id` (`rowMajor`: SPIR-V's RowMajor, HLSL's column_major).
    std::uint32_t sizeOf(std::uint32_t id, bool rowMajor) {
        const Inst* t = type(id);
        if (!t) return 4;
        switch (t->op) {
        case kOpTypeVector: return 4 * m_.w(*t, 3);
        case kOpTypeMatrix: {
            std::uint32_t columns = m_.w(*t, 3), rows = m_.w(m_.instOf(m_.w(*t, 2)), 3);
            return rowMajor ? (rows - 1) * 16 + columns * 4 : (columns - 1) * 16 + rows * 4;
        }
        case kOpTypeArray: {
            std::uint32_t n = std::max(1u, constant(m_.w(*t, 3)));
            std::uint32_t element = sizeOf(m_.w(*t, 2), rowMajor);
            return (n - 1) * roundUp16(element) + element;
        }
        case kOpTypeStruct: return packStruct(id, nullptr);
        default: return 4;
        }
    }
    std::uint32_t arrayStride(std::uint32_t arrayId, bool rowMajor) { return roundUp16(sizeOf(m_.w(m_.instOf(arrayId), 2), rowMajor)); }
    bool startsRegister(std::uint32_t id) const {
        const Inst* t = type(id);
        return t && (t->op == kOpTypeMatrix || t->op == kOpTypeArray || t->op == kOpTypeStruct);
    }
    // Where a member of `size` bytes goes after `end`.
    std::uint32_t place(std::uint32_t end, std::uint32_t memberTypeId, std::uint32_t size) const {
        if (startsRegister(memberTypeId) || (end % 16) + size > 16) return roundUp16(end);
        return end;
    }
    // Packs a struct's members from its start; `explicitOffsets` (bytes, or -1) for a block's.
    std::uint32_t packStruct(std::uint32_t id, const std::vector<int>* explicitOffsets) {
        if (!explicitOffsets)
            if (auto it = structSize_.find(id); it != structSize_.end()) return it->second;
        std::uint32_t n = memberCount(id);
        std::vector<std::uint32_t> sizes(n), offsets(n);
        std::vector<std::pair<std::uint32_t, std::uint32_t>> reserved;
        std::uint32_t end = 0;
        for (std::uint32_t k = 0; k < n; ++k) {
            sizes[k] = sizeOf(memberType(id, k), memberRowMajor(id, k));
            if (explicitOffsets && (*explicitOffsets)[k] >= 0) {
                offsets[k] = std::uint32_t((*explicitOffsets)[k]);
                reserved.push_back({offsets[k], sizes[k]});
                end = std::max(end, offsets[k] + sizes[k]);  // fxc packs the others after the last placed one
            }
        }
        auto overlaps = [&](std::uint32_t at, std::uint32_t size) {
            for (const auto& [from, length] : reserved)
                if (at < from + length && from < at + size) return true;
            return false;
        };
        std::uint32_t total = end;
        const std::vector<bool>* starts = registerStarts_.count(id) ? &registerStarts_.at(id) : nullptr;
        for (std::uint32_t k = 0; k < n; ++k) {
            if (!(explicitOffsets && (*explicitOffsets)[k] >= 0)) {
                if (starts && k < starts->size() && (*starts)[k]) end = roundUp16(end);
                std::uint32_t at = place(end, memberType(id, k), sizes[k]);
                while (overlaps(at, sizes[k])) at = place(roundUp16(at + 1), memberType(id, k), sizes[k]);
                offsets[k] = at;
                end = at + sizes[k];
            }
            total = std::max(total, offsets[k] + sizes[k]);
            memberOffsets_[{id, k}] = offsets[k];
        }
        if (starts && starts->size() == n + 1 && starts->back()) total = std::max(total, roundUp16(end));
        structSize_[id] = total;
        return total;
    }
    // A numbers-only twin of a struct holding objects (rewrite/uniform_object_structs.h): per
    // member and one past the last, whether a register starts there for a member it dropped.
    void setRegisterStarts(std::uint32_t structId, std::vector<bool> starts) { registerStarts_[structId] = std::move(starts); }
    std::uint32_t memberOffset(std::uint32_t structId, std::uint32_t k) {
        if (!memberOffsets_.count({structId, k})) packStruct(structId, nullptr);
        return memberOffsets_[{structId, k}];
    }

    // Whether GLSL can declare the struct with its members at these offsets: std140's alignments
    // (4, 8 for a vec2, 16 for a vec3, vec4, array, matrix or struct), no member inside the
    // previous one as std140 sizes it (an array or matrix to its last register's end, a struct
    // rounded up to 16), array strides std140's. glslang and GL drivers refuse the others.
    // A struct inside the block (`nested`) has no layout(offset = N) in GLSL: its members must be
    // exactly where std140 puts them (a gap D3D leaves, as for a member dropped beside objects
    // (uniform_object_structs.h), needs the flattened block).
    bool glslDeclarable(std::uint32_t structId, bool nested = false) {
        std::uint32_t end = 0;
        for (std::uint32_t k = 0; k < memberCount(structId); ++k) {
            std::uint32_t t = memberType(structId, k), offset = memberOffset(structId, k);
            bool rowMajor = memberRowMajor(structId, k);
            if (offset % std140Alignment(t) != 0 || (k > 0 && offset < end) || !std140Strides(t, rowMajor)) return false;
            const std::uint32_t alignment = std140Alignment(t);
            if (nested && offset != (end + alignment - 1) / alignment * alignment) return false;
            if (holdsIntegerMatrix(t)) return false;  // GLSL has no imat2 (integer_matrices.h)
            end = offset + std140Size(t, rowMajor);
        }
        return true;
    }

    // Writes the computed offsets and strides into the decorations of every struct packed.
    void decorate() {
        for (const auto& [key, offset] : memberOffsets_) {
            if (auto it = offsetWord_.find(key); it != offsetWord_.end()) m_.word(it->second) = offset;
            if (auto it = matrixStrideWord_.find(key); it != matrixStrideWord_.end()) m_.word(it->second) = 16;
            decorateArrays(memberType(key.first, key.second), memberRowMajor(key.first, key.second));
        }
    }

private:
    bool holdsIntegerMatrix(std::uint32_t id) {
        const Inst& t = m_.instOf(id);
        if (t.op == kOpTypeArray) return holdsIntegerMatrix(m_.w(t, 2));
        if (t.op == kOpTypeStruct) {
            for (std::uint32_t k = 0; k < memberCount(id); ++k)
                if (holdsIntegerMatrix(memberType(id, k))) return true;
            return false;
        }
        if (t.op != kOpTypeMatrix) return false;
        const Inst& column = m_.instOf(m_.w(t, 2));
        return m_.instOf(m_.w(column, 2)).op != kOpTypeFloat;
    }
    std::uint32_t std140Alignment(std::uint32_t id) const {
        const Inst& t = m_.instOf(id);
        if (t.op == kOpTypeVector) return m_.w(t, 3) == 2 ? 8 : 16;
        if (t.op == kOpTypeMatrix || t.op == kOpTypeArray || t.op == kOpTypeStruct) return 16;
        return 4;
    }
    std::uint32_t std140Size(std::uint32_t id, bool rowMajor) {
        const Inst& t = m_.instOf(id);
        switch (t.op) {
        case kOpTypeVector: return 4 * m_.w(t, 3);
        case kOpTypeMatrix: return 16 * (rowMajor ? m_.w(m_.instOf(m_.w(t, 2)), 3) : m_.w(t, 3));
        case kOpTypeArray: return arrayStride(id, rowMajor) * std::max(1u, constant(m_.w(t, 3)));
        case kOpTypeStruct: {
            std::uint32_t end = 0;
            for (std::uint32_t k = 0; k < memberCount(id); ++k)
                end = std::max(end, memberOffset(id, k) + std140Size(memberType(id, k), memberRowMajor(id, k)));
            return roundUp16(end);
        }
        default: return 4;
        }
    }
    // Arrays at D3D's stride (16 bytes a register) are std140's where their element is; structs
    // inside must be declarable themselves.
    bool std140Strides(std::uint32_t id, bool rowMajor) {
        const Inst& t = m_.instOf(id);
        if (t.op == kOpTypeStruct) return glslDeclarable(id, true);
        if (t.op != kOpTypeArray) return true;
        std::uint32_t element = m_.w(t, 2);
        if (arrayStride(id, rowMajor) != roundUp16(std140Size(element, rowMajor))) return false;
        return std140Strides(element, rowMajor);
    }

    void decorateArrays(std::uint32_t id, bool rowMajor) {
        const Inst* t = type(id);
        if (!t || t->op != kOpTypeArray) return;
        if (auto it = arrayStrideWord_.find(id); it != arrayStrideWord_.end()) m_.word(it->second) = arrayStride(id, rowMajor);
        decorateArrays(m_.w(*t, 2), rowMajor);
    }

    Module& m_;
    std::set<std::pair<std::uint32_t, std::uint32_t>> rowMajor_;
    using WordAt = std::pair<std::size_t, std::uint32_t>;  // (instruction index, word)
    std::map<std::pair<std::uint32_t, std::uint32_t>, WordAt> offsetWord_, matrixStrideWord_;
    std::map<std::uint32_t, WordAt> arrayStrideWord_;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> memberOffsets_;
    std::map<std::uint32_t, std::uint32_t> structSize_;
    std::map<std::uint32_t, std::vector<bool>> registerStarts_;
};

std::string nameOf(const Module& m, std::uint32_t id) {
    for (const Inst& i : m.insts)
        if (i.op == kOpName && m.w(i, 1) == id) return m.stringAt(i, 2);
    return {};
}
// OpMemberName of every struct, by (struct, member).
std::map<std::pair<std::uint32_t, std::uint32_t>, std::string> memberNames(const Module& m) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::string> out;
    for (const Inst& i : m.insts)
        if (i.op == kOpMemberName) out[{m.w(i, 1), m.w(i, 2)}] = m.stringAt(i, 3);
    return out;
}
std::string memberNameOf(const std::map<std::pair<std::uint32_t, std::uint32_t>, std::string>& names, std::uint32_t id, std::uint32_t k) {
    auto it = names.find({id, k});
    return it == names.end() ? std::string() : it->second;
}

// Whether every scalar `id` reaches is 32 bits wide (the packing here counts 4 bytes a component;
// a block with doubles or 16-bit types keeps glslang's layout).
bool only32BitScalars(const Module& m, std::uint32_t id) {
    const Inst* t = m.defOf(id);
    if (!t) return false;
    switch (t->op) {
    case kOpTypeBool: return true;
    case kOpTypeInt:
    case kOpTypeFloat: return m.w(*t, 2) == 32;
    case kOpTypeVector:
    case kOpTypeMatrix:
    case kOpTypeArray: return only32BitScalars(m, m.w(*t, 2));
    case kOpTypeStruct:
        for (std::uint32_t k = 2; k < t->count; ++k)
            if (!only32BitScalars(m, m.w(*t, k))) return false;
        return true;
    default: return false;
    }
}

// The uniform blocks of the module: (variable, struct type).
std::vector<std::pair<std::uint32_t, std::uint32_t>> uniformBlocks(const Module& m) {
    std::set<std::uint32_t> blockTypes;
    for (const Inst& i : m.insts)
        if (i.op == kOpDecorate && m.w(i, 2) == kDecBlock) blockTypes.insert(m.w(i, 1));
    std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
    for (const Inst& i : m.insts) {
        if (i.op != kOpVariable || m.w(i, 3) != kStorageUniform) continue;
        const Inst* ptr = m.defOf(i.type);
        if (!ptr || ptr->op != kOpTypePointer) continue;
        std::uint32_t pointee = m.w(*ptr, 3);
        if (blockTypes.count(pointee)) out.push_back({i.result, pointee});
    }
    return out;
}

// packoffset (cbuffer members) and register(cN) ($Global members), in bytes; -1 where none.
std::vector<int> explicitOffsets(const std::map<std::pair<std::uint32_t, std::uint32_t>, std::string>& names, std::uint32_t structId,
                                 const std::string& block, const EffectSyntax& syntax, std::uint32_t n) {
    std::vector<int> out(n, -1);
    for (std::uint32_t k = 0; k < n; ++k) {
        std::string member = memberNameOf(names, structId, k);
        for (const FxGlobal& g : syntax.globals) {
            if (g.name != member) continue;
            if (block == "$Global" && g.cbuffer.empty() && g.registerClass == 'c' && g.registerIndex >= 0) out[k] = 16 * g.registerIndex;
            if (block != "$Global" && g.cbuffer == block && g.packOffset >= 0) out[k] = 4 * g.packOffset;
        }
    }
    return out;
}

// The members of a packed struct as the reflection lists them, nested structs with their own.
std::vector<UniformMember> describeMembers(const Module& m, Packer& packer, std::uint32_t structId,
                                           const std::map<std::pair<std::uint32_t, std::uint32_t>, std::string>& names) {
    std::vector<UniformMember> out;
    for (std::uint32_t k = 0; k < packer.memberCount(structId); ++k) {
        UniformMember u;
        u.name = memberNameOf(names, structId, k);
        std::uint32_t t = packer.memberType(structId, k);
        bool rowMajor = packer.memberRowMajor(structId, k);
        u.offset = int(packer.memberOffset(structId, k));
        u.size = int(packer.sizeOf(t, rowMajor));
        const Inst* ti = packer.type(t);
        // An array of arrays is one array to D3D's reflection (float a[2][3]: 6 elements), whose
        // stride is the innermost one: each inner array fills whole registers, so they follow on.
        while (ti && ti->op == kOpTypeArray) {
            u.arrayStride = int(packer.arrayStride(t, rowMajor));
            t = m.w(*ti, 2);
            ti = packer.type(t);
        }
        if (ti && ti->op == kOpTypeMatrix) {
            u.matrixStride = 16;
            u.hlslRowMajor = !rowMajor;
        }
        if (ti && ti->op == kOpTypeStruct) u.members = describeMembers(m, packer, t, names);
        out.push_back(std::move(u));
    }
    return out;
}

}  // namespace

std::vector<PackedBlock> packConstantBuffers(ParsedSpirv& spirv, const EffectSyntax& syntax) {
    Module m(spirv);
    std::vector<PackedBlock> out;
    Packer packer(m);
    const auto names = memberNames(m);
    std::map<std::uint32_t, std::vector<bool>> registerStarts;
    for (const Inst& i : m.insts) {
        if (i.op != kOpName) continue;
        const std::string name = m.stringAt(i, 2);
        if (name.rfind(kNumbersStructPrefix, 0) != 0) continue;
        if (const FxStruct* original = syntax.findStruct(name.substr(std::string(kNumbersStructPrefix).size())))
            registerStarts[m.w(i, 1)] = numbersStructRegisterStarts(syntax, *original);
    }
    for (const auto& [id, starts] : registerStarts) packer.setRegisterStarts(id, starts);
    for (const auto& [variable, structId] : uniformBlocks(m)) {
        if (!only32BitScalars(m, structId)) continue;
        PackedBlock b;
        b.variable = variable;
        b.type = structId;
        b.name = nameOf(m, structId);
        std::uint32_t n = packer.memberCount(structId);
        std::vector<int> placed = explicitOffsets(names, structId, b.name, syntax, n);
        b.size = int(roundUp16(packer.packStruct(structId, &placed)));
        b.members = describeMembers(m, packer, structId, names);
        b.glslDeclarable = packer.glslDeclarable(structId);
        b.registerStarts = registerStarts;
        out.push_back(std::move(b));
    }
    packer.decorate();
    return out;
}

namespace {

// A place in the flattened block: a byte offset plus dynamic terms (id * stride bytes).
struct Place {
    std::uint32_t offset = 0;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> terms;  // (uint id, stride)
};

// What an access chain into the block points at.
struct Pointer {
    Place place;
    std::uint32_t type = 0;
    bool rowMajor = false;           // SPIR-V RowMajor of the enclosing matrix member
    std::uint32_t componentStride = 4;  // 16 for a column of a RowMajor matrix
    std::uint32_t topMember = 0;
};

class Flattener {
public:
    Flattener(Module& m, Packer& packer, PackedBlock& block, std::uint32_t bound) : m_(m), packer_(packer), block_(block), next_(bound) {}

    // Rewrites the module; false (and the module untouched) when a use of the block cannot be
    // rebuilt from registers.
    bool run();

private:
    std::uint32_t fresh() { return next_++; }
    void emit(std::vector<std::uint32_t>& to, std::uint32_t op, std::initializer_list<std::uint32_t> operands) {
        to.push_back(std::uint32_t(operands.size() + 1) << 16 | op);
        to.insert(to.end(), operands);
    }
    void emitV(std::vector<std::uint32_t>& to, std::uint32_t op, const std::vector<std::uint32_t>& operands) {
        to.push_back(std::uint32_t(operands.size() + 1) << 16 | op);
        to.insert(to.end(), operands.begin(), operands.end());
    }
    std::uint32_t uintConstant(std::uint32_t v) {
        auto it = constants_.find(v);
        if (it != constants_.end()) return it->second;
        std::uint32_t id = fresh();
        emit(globals_, kOpConstant, {uint_, id, v});
        constants_[v] = id;
        return id;
    }
    std::uint32_t asUint(std::uint32_t id, std::vector<std::uint32_t>& body) {
        auto t = m_.typeOf.find(id);
        const Inst* ti = t == m_.typeOf.end() ? nullptr : m_.defOf(t->second);
        if (ti && ti->op == kOpTypeInt && m_.w(*ti, 3) == 0) return id;
        std::uint32_t r = fresh();
        emit(body, kOpBitcast, {uint_, r, id});
        return r;
    }
    bool step(Pointer& p, std::uint32_t index, std::vector<std::uint32_t>& body);
    std::uint32_t load(const Pointer& p, std::uint32_t type, std::vector<std::uint32_t>& body);
    std::uint32_t loadScalar(const Place& at, std::uint32_t type, std::uint32_t topMember, std::vector<std::uint32_t>& body);
    void noteRead(const Place& at, std::uint32_t topMember);

    Module& m_;
    Packer& packer_;
    PackedBlock& block_;
    std::uint32_t next_;
    std::uint32_t uint_ = 0, uvec4_ = 0, registerPointer_ = 0;
    std::vector<std::uint32_t> globals_;  // new types and constants, before the first function
    std::map<std::uint32_t, std::uint32_t> constants_;
    std::map<std::uint32_t, Pointer> pointers_;  // access chains into the block
    std::set<std::pair<std::uint32_t, std::uint32_t>> bytesRead_;
    std::set<std::uint32_t> membersRead_;
};

bool Flattener::step(Pointer& p, std::uint32_t index, std::vector<std::uint32_t>& body) {
    const Inst* t = packer_.type(p.type);
    if (!t) return false;
    bool constant = packer_.isConstant(index);
    std::uint32_t value = packer_.constant(index);
    auto add = [&](std::uint32_t stride) {
        if (constant) p.place.offset += value * stride;
        else p.place.terms.push_back({asUint(index, body), stride});
    };
    switch (t->op) {
    case kOpTypeStruct:
        if (!constant || value >= packer_.memberCount(p.type)) return false;
        p.place.offset += packer_.memberOffset(p.type, value);
        p.rowMajor = packer_.memberRowMajor(p.type, value);
        p.componentStride = 4;
        p.type = packer_.memberType(p.type, value);
        return true;
    case kOpTypeArray:
        add(packer_.arrayStride(p.type, p.rowMajor));
        p.type = m_.w(*t, 2);
        return true;
    case kOpTypeMatrix:
        add(p.rowMajor ? 4 : 16);
        p.componentStride = p.rowMajor ? 16 : 4;
        p.type = m_.w(*t, 2);
        return true;
    case kOpTypeVector:
        add(p.componentStride);
        p.type = m_.w(*t, 2);
        return true;
    default: return false;
    }
}

void Flattener::noteRead(const Place& at, std::uint32_t topMember) {
    membersRead_.insert(topMember);
    bool dynamicRegister = false;
    for (const auto& [id, stride] : at.terms) dynamicRegister |= stride % 16 == 0;
    if (dynamicRegister) {
        const UniformMember& m = block_.members[topMember];
        bytesRead_.insert({std::uint32_t(m.offset), std::uint32_t(m.size)});
    } else if (!at.terms.empty()) {
        bytesRead_.insert({at.offset / 16 * 16, 16});  // a dynamic component: the whole register
    } else {
        bytesRead_.insert({at.offset, 4});
    }
}

std::uint32_t Flattener::loadScalar(const Place& at, std::uint32_t type, std::uint32_t topMember, std::vector<std::uint32_t>& body) {
    noteRead(at, topMember);
    std::uint32_t reg = uintConstant(at.offset / 16);
    std::uint32_t component = 0;
    bool dynamicComponent = false;
    for (const auto& [id, stride] : at.terms) {
        std::uint32_t scaled = id;
        if (stride % 16 == 0) {
            if (stride != 16) {
                scaled = fresh();
                emit(body, kOpIMul, {uint_, scaled, id, uintConstant(stride / 16)});
            }
            std::uint32_t sum = fresh();
            emit(body, kOpIAdd, {uint_, sum, reg, scaled});
            reg = sum;
        } else {
            if (!dynamicComponent) {
                component = uintConstant((at.offset % 16) / 4);
                dynamicComponent = true;
            }
            std::uint32_t sum = fresh();
            emit(body, kOpIAdd, {uint_, sum, component, scaled});  // stride 4: one component per index
            component = sum;
        }
    }
    std::uint32_t pointer = fresh(), registerValue = fresh(), bits = fresh();
    emit(body, kOpAccessChain, {registerPointer_, pointer, block_.variable, uintConstant(0), reg});
    emit(body, kOpLoad, {uvec4_, registerValue, pointer});
    if (dynamicComponent) emit(body, kOpVectorExtractDynamic, {uint_, bits, registerValue, component});
    else emit(body, kOpCompositeExtract, {uint_, bits, registerValue, (at.offset % 16) / 4});
    const Inst* t = packer_.type(type);
    if (!t) return bits;
    if (t->op == kOpTypeBool) {
        std::uint32_t r = fresh();
        emit(body, kOpINotEqual, {type, r, bits, uintConstant(0)});
        return r;
    }
    if (t->op == kOpTypeInt && m_.w(*t, 3) == 0 && m_.w(*t, 2) == 32) return bits;
    std::uint32_t r = fresh();
    emit(body, kOpBitcast, {type, r, bits});
    return r;
}

std::uint32_t Flattener::load(const Pointer& p, std::uint32_t type, std::vector<std::uint32_t>& body) {
    const Inst* t = packer_.type(type);
    if (!t) return 0;
    std::vector<std::uint32_t> parts{type, 0};
    auto part = [&](std::uint32_t offset, std::uint32_t partType, bool rowMajor, std::uint32_t componentStride) {
        Pointer q = p;
        q.place.offset += offset;
        q.rowMajor = rowMajor;
        q.componentStride = componentStride;
        std::uint32_t v = load(q, partType, body);
        parts.push_back(v);
        return v != 0;
    };
    bool ok = true;
    switch (t->op) {
    case kOpTypeVector:
        for (std::uint32_t k = 0; k < m_.w(*t, 3); ++k) ok &= part(k * p.componentStride, m_.w(*t, 2), p.rowMajor, 4);
        break;
    case kOpTypeMatrix:
        for (std::uint32_t c = 0; c < m_.w(*t, 3); ++c)
            ok &= part(p.rowMajor ? c * 4 : c * 16, m_.w(*t, 2), p.rowMajor, p.rowMajor ? 16 : 4);
        break;
    case kOpTypeArray: {
        std::uint32_t stride = packer_.arrayStride(type, p.rowMajor);
        for (std::uint32_t i = 0; i < packer_.constant(m_.w(*t, 3)); ++i) ok &= part(i * stride, m_.w(*t, 2), p.rowMajor, 4);
        break;
    }
    case kOpTypeStruct:
        for (std::uint32_t k = 0; k < packer_.memberCount(type); ++k)
            ok &= part(packer_.memberOffset(type, k), packer_.memberType(type, k), packer_.memberRowMajor(type, k), 4);
        break;
    case kOpTypeBool:
    case kOpTypeInt:
    case kOpTypeFloat: return loadScalar(p.place, type, p.topMember, body);
    default: return 0;
    }
    if (!ok) return 0;
    parts[1] = fresh();
    emitV(body, kOpCompositeConstruct, parts);
    return parts[1];
}

bool Flattener::run() {
    // Types: uint and uvec4 (reused where the module has them), uvec4[N], the block struct.
    for (const Inst& i : m_.insts)
        if (i.op == kOpTypeInt && m_.w(i, 2) == 32 && m_.w(i, 3) == 0 && !uint_) uint_ = i.result;
    if (!uint_) {
        uint_ = fresh();
        emit(globals_, kOpTypeInt, {uint_, 32, 0});
    }
    for (const Inst& i : m_.insts)
        if (i.op == kOpTypeVector && m_.w(i, 2) == uint_ && m_.w(i, 3) == 4 && !uvec4_) uvec4_ = i.result;
    if (!uvec4_) {
        uvec4_ = fresh();
        emit(globals_, kOpTypeVector, {uvec4_, uint_, 4});
    }
    std::uint32_t registers = std::max(1, block_.size / 16);
    std::uint32_t array = fresh(), blockType = fresh(), blockPointer = fresh();
    registerPointer_ = fresh();
    emit(globals_, kOpTypeArray, {array, uvec4_, uintConstant(registers)});
    emit(globals_, kOpTypeStruct, {blockType, array});
    emit(globals_, kOpTypePointer, {blockPointer, kStorageUniform, blockType});
    emit(globals_, kOpTypePointer, {registerPointer_, kStorageUniform, uvec4_});

    // Function bodies: chains into the block are followed, loads through them rebuilt.
    std::vector<std::uint32_t> functions;
    std::size_t firstFunction = m_.insts.size();
    for (const Inst& i : m_.insts) {
        if (i.op == kOpFunction && firstFunction == m_.insts.size()) firstFunction = i.at;
        if (i.at < firstFunction) continue;
        bool chain = (i.op == kOpAccessChain || i.op == kOpInBoundsAccessChain) &&
                     (m_.w(i, 3) == block_.variable || pointers_.count(m_.w(i, 3)));
        if (chain) {
            Pointer p;
            std::uint32_t first = 4;
            if (m_.w(i, 3) == block_.variable) {
                p.type = block_.type;
                if (i.count > 4) p.topMember = packer_.constant(m_.w(i, 4));
                if (i.count > 4 && (!packer_.isConstant(m_.w(i, 4)) || p.topMember >= block_.members.size())) return false;
            } else {
                p = pointers_[m_.w(i, 3)];
            }
            for (std::uint32_t k = first; k < i.count; ++k)
                if (!step(p, m_.w(i, k), functions)) return false;
            pointers_[i.result] = p;
            continue;
        }
        if (i.op == kOpLoad && pointers_.count(m_.w(i, 3))) {
            const Pointer& p = pointers_[m_.w(i, 3)];
            if (p.type == block_.type) return false;  // the whole block: never from HLSL
            std::uint32_t v = load(p, i.type, functions);
            if (!v) return false;
            // The load's result id names the rebuilt value: a copy keeps every use as it was.
            emit(functions, 83 /* OpCopyObject */, {i.type, i.result, v});
            continue;
        }
        for (std::uint16_t u : i.uses) {
            std::uint32_t id = m_.w(i, u);
            if (id == block_.variable || pointers_.count(id)) return false;  // another use of the block
        }
        functions.insert(functions.end(), m_.words(i).begin(), m_.words(i).end());
    }

    // Reassemble: names and decorations of the new struct, the variable moved after the new types.
    std::vector<std::uint32_t> out;
    std::vector<std::uint32_t> names, decorations;
    auto pushString = [](std::vector<std::uint32_t>& to, const std::string& s) {
        for (std::size_t k = 0; k <= s.size(); k += 4) {
            std::uint32_t word = 0;
            for (std::size_t b = 0; b < 4 && k + b < s.size(); ++b) word |= std::uint32_t(std::uint8_t(s[k + b])) << (8 * b);
            to.push_back(word);
        }
    };
    std::vector<std::uint32_t> s1, s2;
    pushString(s1, block_.name);
    pushString(s2, "registers");
    names.push_back(std::uint32_t(2 + s1.size()) << 16 | kOpName);
    names.push_back(blockType);
    names.insert(names.end(), s1.begin(), s1.end());
    names.push_back(std::uint32_t(3 + s2.size()) << 16 | kOpMemberName);
    names.push_back(blockType);
    names.push_back(0);
    names.insert(names.end(), s2.begin(), s2.end());
    emit(decorations, kOpDecorate, {blockType, kDecBlock});
    emit(decorations, kOpMemberDecorate, {blockType, 0, kDecOffset, 0});
    emit(decorations, kOpDecorate, {array, kDecArrayStride, 16});
    bool namesDone = false, decorationsDone = false;
    std::vector<std::uint32_t> variable;
    for (const Inst& i : m_.insts) {
        if (i.at >= firstFunction) break;
        bool annotation = i.op == kOpDecorate || i.op == kOpMemberDecorate || (i.op >= 73 && i.op <= 75) || i.op == 332 || i.op == 5632 || i.op == 5633;
        // Types, constants and variables (OpModuleProcessed 330 and OpExecutionModeId 331 come earlier).
        bool declaration = i.op >= 19 && !annotation && i.op != 317 /* OpNoLine */ && i.op != 330 && i.op != 331;
        if (!namesDone && (annotation || declaration)) {
            out.insert(out.end(), names.begin(), names.end());
            namesDone = true;
        }
        if (!decorationsDone && declaration) {
            out.insert(out.end(), decorations.begin(), decorations.end());
            decorationsDone = true;
        }
        if (i.result == block_.variable) {
            emit(variable, kOpVariable, {blockPointer, block_.variable, kStorageUniform});
            continue;
        }
        out.insert(out.end(), m_.words(i).begin(), m_.words(i).end());
    }
    if (!namesDone || !decorationsDone || variable.empty()) return false;
    out.insert(out.end(), globals_.begin(), globals_.end());
    out.insert(out.end(), variable.begin(), variable.end());
    out.insert(out.end(), functions.begin(), functions.end());
    std::vector<SpirvInstruction> instructions;
    for (std::size_t at = 0; at < out.size(); at += out[at] >> 16)
        instructions.push_back({std::vector<std::uint32_t>(out.begin() + std::ptrdiff_t(at), out.begin() + std::ptrdiff_t(at + (out[at] >> 16)))});
    m_.spirv.instructions = std::move(instructions);
    m_.spirv.setIdBound(next_);

    // What the shader reads: merged byte ranges, and the members they belong to.
    std::uint32_t from = 0, to = 0;
    bool open = false;
    for (const auto& [offset, size] : bytesRead_) {
        if (open && offset <= to) {
            to = std::max(to, offset + size);
            continue;
        }
        if (open) block_.rangesRead.push_back({int(from), int(to - from), -1});
        from = offset;
        to = offset + size;
        open = true;
    }
    if (open) block_.rangesRead.push_back({int(from), int(to - from), -1});
    for (std::uint32_t k : membersRead_) block_.membersRead.push_back(block_.members[k].name);
    block_.flattened = true;
    return true;
}

}  // namespace

bool flattenConstantBuffer(ParsedSpirv& spirv, PackedBlock& block) {
    Module m(spirv);
    Packer packer(m);
    for (const auto& [id, starts] : block.registerStarts) packer.setRegisterStarts(id, starts);
    // The struct's D3D offsets as packConstantBuffers decorated them (explicit placements included).
    std::vector<int> placed;
    for (const UniformMember& u : block.members) placed.push_back(u.offset);
    if (placed.size() != packer.memberCount(block.type)) return false;
    packer.packStruct(block.type, &placed);
    Flattener f(m, packer, block, spirv.idBound());
    return f.run();
}

}  // namespace fxport::xlate
