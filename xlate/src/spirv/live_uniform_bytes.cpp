// See live_uniform_bytes.h. Every value gets a mask of live scalar components ("leaves", in the
// order SPIR-V nests them: a matrix column by column, an array element by element, a struct member
// by member). Effects (stores, branches, returns, image writes...) make their operands wholly
// live; each operation passes its result's live components back to the operand components they
// are computed from; a load from a uniform block turns its live components into byte offsets.
#include "spirv/live_uniform_bytes.h"

#include <spirv-tools/libspirv.h>

#include <set>

namespace fxport::xlate {

namespace {

// SPIR-V opcodes, decorations and GLSL.std.450 instructions read here.
namespace op {
constexpr std::uint32_t ExtInst = 12, TypeBool = 20, TypeInt = 21, TypeFloat = 22, TypeVector = 23, TypeMatrix = 24,
                        TypeArray = 28, TypeStruct = 30, TypePointer = 32, Constant = 43, Function = 54, FunctionEnd = 56,
                        FunctionCall = 57, Variable = 59, Load = 61, AccessChain = 65, InBoundsAccessChain = 66,
                        Decorate = 71, MemberDecorate = 72, VectorExtractDynamic = 77, VectorShuffle = 79,
                        CompositeConstruct = 80, CompositeExtract = 81, CompositeInsert = 82, CopyObject = 83, Transpose = 84,
                        VectorTimesMatrix = 144, MatrixTimesVector = 145, MatrixTimesMatrix = 146, OuterProduct = 147, Phi = 245;
}  // namespace op
constexpr std::uint32_t kDecRowMajor = 4, kDecArrayStride = 6, kDecMatrixStride = 7, kDecOffset = 35, kDecBlock = 2;
constexpr std::uint32_t kStorageUniform = 2;
constexpr std::size_t kMaxLeaves = 1u << 16;
constexpr int kMaxDepth = 64;  // type nesting followed (glslang's types nest far less)

struct Inst {
    std::uint32_t op = 0, type = 0, result = 0;
    std::vector<std::uint32_t> ids;   // id operands in order (result type and result excluded)
    std::vector<std::uint32_t> lits;  // literal operands in order
};

// Operations whose result component i is computed from component i of each operand of the
// result's shape (an operand of another shape, a scalar factor or a condition, counts wholly).
bool componentwise(std::uint32_t o) {
    return (o >= 109 && o <= 116) || (o >= 126 && o <= 143) || (o >= 156 && o <= 157) || (o >= 164 && o <= 191) ||
           (o >= 194 && o <= 200) || o == op::CopyObject || o == 124 /* OpBitcast */;
}

bool componentwiseGlsl(std::uint32_t e) {
    return (e >= 1 && e <= 32) || (e >= 37 && e <= 50) || e == 53 || (e >= 73 && e <= 75) || (e >= 79 && e <= 81);
}

class Analysis {
public:
    bool parse(const std::vector<std::uint32_t>& words);
    bool run();
    std::map<std::uint32_t, std::vector<LiveRange>> ranges() const;

private:
    std::vector<Inst> insts_;
    std::size_t firstFunction_ = 0;
    std::map<std::uint32_t, std::size_t> defs_;  // id -> instruction
    std::map<std::uint32_t, std::uint32_t> constants_;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> memberOffset_, matrixStride_;
    std::set<std::pair<std::uint32_t, std::uint32_t>> rowMajor_;
    std::map<std::uint32_t, std::uint32_t> arrayStride_;
    std::set<std::uint32_t> blocks_;  // struct types decorated Block
    std::map<std::uint32_t, std::size_t> leafCache_;
    std::map<std::uint32_t, std::vector<char>> live_;
    std::map<std::uint32_t, std::set<std::uint32_t>> bytes_;  // block variable -> live byte offsets
    bool changed_ = false;

    const Inst* def(std::uint32_t id) const {
        auto it = defs_.find(id);
        return it == defs_.end() ? nullptr : &insts_[it->second];
    }
    std::size_t leaves(std::uint32_t type);
    std::size_t leafOffset(std::uint32_t type, const std::vector<std::uint32_t>& path, std::size_t from);
    std::uint32_t typeAt(std::uint32_t type, const std::vector<std::uint32_t>& path, std::size_t from);
    std::vector<char>& mask(std::uint32_t id);
    void mark(std::uint32_t id, std::size_t leaf);
    void markAll(std::uint32_t id);
    void markRange(std::uint32_t id, std::size_t at, const std::vector<char>& r, std::size_t from, std::size_t count);
    void visit(const Inst& i);
    bool uniformLoad(const Inst& load);
    bool leafBytes(std::uint32_t type, std::uint32_t base, std::uint32_t stride, bool rowMajor, std::uint32_t componentStride,
                   std::vector<std::pair<std::uint32_t, std::uint32_t>>& out, int depth = 0);
};

bool Analysis::parse(const std::vector<std::uint32_t>& words) {
    spv_context context = spvContextCreate(SPV_ENV_VULKAN_1_0);
    auto onInstruction = [](void* user, const spv_parsed_instruction_t* p) -> spv_result_t {
        auto* self = static_cast<Analysis*>(user);
        Inst i;
        i.op = p->opcode;
        i.type = p->type_id;
        i.result = p->result_id;
        for (std::uint16_t k = 0; k < p->num_operands; ++k) {
            const spv_parsed_operand_t& o = p->operands[k];
            if (o.type == SPV_OPERAND_TYPE_RESULT_ID || o.type == SPV_OPERAND_TYPE_TYPE_ID) continue;
            if (o.type == SPV_OPERAND_TYPE_ID) i.ids.push_back(p->words[o.offset]);
            else if (o.num_words == 1) i.lits.push_back(p->words[o.offset]);
        }
        if (i.result) self->defs_[i.result] = self->insts_.size();
        if (i.op == op::Function && self->firstFunction_ == 0) self->firstFunction_ = self->insts_.size();
        self->insts_.push_back(std::move(i));
        return SPV_SUCCESS;
    };
    spv_result_t r = spvBinaryParse(context, this, words.data(), words.size(), nullptr, onInstruction, nullptr);
    spvContextDestroy(context);
    if (r != SPV_SUCCESS) return false;
    for (std::size_t k = 0; k < firstFunction_; ++k) {
        const Inst& i = insts_[k];
        if (i.op == op::Constant && i.lits.size() == 1) constants_[i.result] = i.lits[0];
        if (i.op == op::Decorate && i.ids.size() == 1 && !i.lits.empty()) {
            if (i.lits[0] == kDecArrayStride && i.lits.size() == 2) arrayStride_[i.ids[0]] = i.lits[1];
            if (i.lits[0] == kDecBlock) blocks_.insert(i.ids[0]);
        }
        if (i.op == op::MemberDecorate && i.ids.size() == 1 && i.lits.size() >= 2) {
            auto key = std::make_pair(i.ids[0], i.lits[0]);
            if (i.lits[1] == kDecOffset && i.lits.size() == 3) memberOffset_[key] = i.lits[2];
            if (i.lits[1] == kDecMatrixStride && i.lits.size() == 3) matrixStride_[key] = i.lits[2];
            if (i.lits[1] == kDecRowMajor) rowMajor_.insert(key);
        }
    }
    return firstFunction_ > 0;
}

// Scalar components of a value of `type`; 0 for what has none (pointers, images, void).
std::size_t Analysis::leaves(std::uint32_t type) {
    if (auto it = leafCache_.find(type); it != leafCache_.end()) return it->second;
    leafCache_[type] = 0;  // a type that contains itself (a corrupt module) has no leaves
    const Inst* t = def(type);
    std::size_t n = 0;
    if (!t) n = 0;
    else if (t->op == op::TypeBool || t->op == op::TypeInt || t->op == op::TypeFloat) n = 1;
    else if ((t->op == op::TypeVector || t->op == op::TypeMatrix) && t->ids.size() == 1 && t->lits.size() == 1)
        n = std::min<std::size_t>(kMaxLeaves + 1, std::size_t(t->lits[0]) * leaves(t->ids[0]));
    else if (t->op == op::TypeArray && t->ids.size() == 2 && constants_.count(t->ids[1]))
        n = std::min<std::size_t>(kMaxLeaves + 1, std::size_t(constants_[t->ids[1]]) * leaves(t->ids[0]));
    else if (t->op == op::TypeStruct)
        for (std::uint32_t m : t->ids) n = std::min(kMaxLeaves + 1, n + leaves(m));
    leafCache_[type] = n;
    return n;
}

// The type reached by the literal indices path[from..] into `type`, and the first leaf it covers.
std::uint32_t Analysis::typeAt(std::uint32_t type, const std::vector<std::uint32_t>& path, std::size_t from) {
    for (std::size_t k = from; k < path.size(); ++k) {
        const Inst* t = def(type);
        if (!t || t->ids.empty()) return 0;
        if (t->op == op::TypeStruct) {
            if (path[k] >= t->ids.size()) return 0;
            type = t->ids[path[k]];
        } else {
            type = t->ids[0];
        }
    }
    return type;
}

std::size_t Analysis::leafOffset(std::uint32_t type, const std::vector<std::uint32_t>& path, std::size_t from) {
    std::size_t at = 0;
    for (std::size_t k = from; k < path.size(); ++k) {
        const Inst* t = def(type);
        if (!t || t->ids.empty()) return 0;
        if (t->op == op::TypeStruct) {
            for (std::uint32_t m = 0; m < path[k] && m < t->ids.size(); ++m) at += leaves(t->ids[m]);
            type = path[k] < t->ids.size() ? t->ids[path[k]] : 0;
        } else {
            type = t->ids[0];
            at += path[k] * leaves(type);
        }
    }
    return at;
}

// The live mask of a value: one flag per leaf, one flag for a value without leaves.
std::vector<char>& Analysis::mask(std::uint32_t id) {
    auto it = live_.find(id);
    if (it != live_.end()) return it->second;
    const Inst* d = def(id);
    std::size_t n = d ? leaves(d->type) : 0;
    return live_[id] = std::vector<char>(std::max<std::size_t>(1, n), 0);
}

void Analysis::mark(std::uint32_t id, std::size_t leaf) {
    std::vector<char>& m = mask(id);
    if (leaf < m.size() && !m[leaf]) m[leaf] = 1, changed_ = true;
}

void Analysis::markAll(std::uint32_t id) {
    std::vector<char>& m = mask(id);
    for (char& c : m)
        if (!c) c = 1, changed_ = true;
}

// Leaves [at, at + count) of `id` from flags r[from, from + count).
void Analysis::markRange(std::uint32_t id, std::size_t at, const std::vector<char>& r, std::size_t from, std::size_t count) {
    for (std::size_t k = 0; k < count && from + k < r.size(); ++k)
        if (r[from + k]) mark(id, at + k);
}

void Analysis::visit(const Inst& i) {
    const bool value = i.result && i.type && leaves(i.type) > 0;
    if (!value) {  // an effect, a void call, a pointer: everything it uses counts
        if (i.result && (i.op == op::Variable || i.op == op::AccessChain || i.op == op::InBoundsAccessChain || i.op == op::Load)) {
            if (live_.count(i.result) && mask(i.result)[0])
                for (std::uint32_t id : i.ids) markAll(id);
            return;
        }
        for (std::uint32_t id : i.ids) markAll(id);
        return;
    }
    const std::vector<char> r = mask(i.result);  // a copy: marking may grow the map
    bool any = false;
    for (char c : r) any = any || c;
    // Calls, atomics and what writes through a pointer (modf's and frexp's out parameter) act
    // even when their result is unread.
    bool effect = i.op == op::FunctionCall || (i.op >= 227 && i.op <= 242);
    for (std::uint32_t id : i.ids) {
        if (i.op == op::Load) break;
        const Inst* d = def(id);
        const Inst* t = d ? def(d->type) : nullptr;
        effect = effect || (t && t->op == op::TypePointer);
    }
    if (!any && !effect) return;
    const std::size_t n = r.size();
    auto sameShape = [&](std::uint32_t id) {
        const Inst* d = def(id);
        return d && leaves(d->type) == n;
    };
    auto shapeOf = [&](std::uint32_t id, std::uint32_t& columns, std::uint32_t& rows) {
        const Inst* d = def(id);
        const Inst* t = d ? def(d->type) : nullptr;
        if (!t || t->lits.empty()) return false;
        columns = t->op == op::TypeMatrix ? t->lits[0] : 1;
        rows = t->op == op::TypeMatrix ? std::uint32_t(leaves(t->ids[0])) : t->lits[0];
        return t->op == op::TypeMatrix || t->op == op::TypeVector;
    };
    std::uint32_t ac = 0, ar = 0, bc = 0, br = 0;
    switch (i.op) {
    case op::Load:
        markAll(i.ids[0]);
        return;
    case op::CompositeExtract:
        if (const Inst* d = def(i.ids[0])) markRange(i.ids[0], leafOffset(d->type, i.lits, 0), r, 0, n);
        return;
    case op::CompositeInsert:
        if (i.ids.size() == 2) {
            std::size_t at = leafOffset(i.type, i.lits, 0), count = leaves(typeAt(i.type, i.lits, 0));
            markRange(i.ids[0], 0, r, at, count);
            std::vector<char> rest = r;
            for (std::size_t k = at; k < at + count && k < rest.size(); ++k) rest[k] = 0;
            markRange(i.ids[1], 0, rest, 0, n);
        }
        return;
    case op::CompositeConstruct: {
        std::size_t at = 0;
        for (std::uint32_t id : i.ids) {
            const Inst* d = def(id);
            std::size_t count = d ? leaves(d->type) : 0;
            if (count == 0) {
                markAll(id);
                continue;
            }
            markRange(id, 0, r, at, count);
            at += count;
        }
        return;
    }
    case op::VectorShuffle:
        if (i.ids.size() == 2) {
            const Inst* d = def(i.ids[0]);
            std::uint32_t first = d ? std::uint32_t(leaves(d->type)) : 0;
            for (std::size_t k = 0; k < i.lits.size() && k < n; ++k) {
                if (!r[k] || i.lits[k] == 0xFFFFFFFFu) continue;
                if (i.lits[k] < first) mark(i.ids[0], i.lits[k]);
                else mark(i.ids[1], i.lits[k] - first);
            }
        }
        return;
    case op::Phi:
        for (std::size_t k = 0; k + 1 < i.ids.size(); k += 2) {
            if (sameShape(i.ids[k])) markRange(i.ids[k], 0, r, 0, n);
            else markAll(i.ids[k]);
        }
        return;
    case op::Transpose:  // result column c, row j is operand column j, row c
        if (shapeOf(i.ids[0], ac, ar))
            for (std::size_t k = 0; k < n; ++k)
                if (r[k]) mark(i.ids[0], (k % ac) * ar + k / ac);
        return;
    case op::MatrixTimesVector:  // result[j] = sum over c of M[c][j] * v[c]
        if (i.ids.size() == 2 && shapeOf(i.ids[0], ac, ar)) {
            for (std::size_t j = 0; j < n; ++j)
                for (std::uint32_t c = 0; r[j] && c < ac; ++c) mark(i.ids[0], c * ar + j), mark(i.ids[1], c);
            return;
        }
        break;
    case op::VectorTimesMatrix:  // result[c] = sum over j of v[j] * M[c][j]
        if (i.ids.size() == 2 && shapeOf(i.ids[1], bc, br)) {
            for (std::size_t c = 0; c < n; ++c)
                for (std::uint32_t j = 0; r[c] && j < br; ++j) mark(i.ids[1], c * br + j), mark(i.ids[0], j);
            return;
        }
        break;
    case op::MatrixTimesMatrix:  // result[c][j] = sum over k of A[k][j] * B[c][k]
        if (i.ids.size() == 2 && shapeOf(i.ids[0], ac, ar) && shapeOf(i.ids[1], bc, br) && ar > 0) {
            for (std::size_t x = 0; x < n; ++x)
                for (std::uint32_t k = 0; r[x] && k < ac; ++k) mark(i.ids[0], k * ar + x % ar), mark(i.ids[1], (x / ar) * br + k);
            return;
        }
        break;
    case op::OuterProduct:  // result[c][j] = a[j] * b[c]
        if (i.ids.size() == 2 && shapeOf(i.ids[0], ac, ar) && ar > 0) {
            for (std::size_t x = 0; x < n; ++x)
                if (r[x]) mark(i.ids[0], x % ar), mark(i.ids[1], x / ar);
            return;
        }
        break;
    case op::ExtInst:
        if (!i.lits.empty() && componentwiseGlsl(i.lits[0])) {
            for (std::size_t k = 1; k < i.ids.size(); ++k) {
                if (sameShape(i.ids[k])) markRange(i.ids[k], 0, r, 0, n);
                else markAll(i.ids[k]);
            }
            return;
        }
        break;
    default:
        if (componentwise(i.op)) {
            for (std::uint32_t id : i.ids) {
                if (sameShape(id)) markRange(id, 0, r, 0, n);
                else markAll(id);
            }
            return;
        }
        break;
    }
    for (std::uint32_t id : i.ids) markAll(id);
}

bool Analysis::run() {
    for (std::size_t k = firstFunction_; k < insts_.size(); ++k)  // masks stay small
        if (insts_[k].type && leaves(insts_[k].type) > kMaxLeaves) return false;
    // Backward over the function bodies until nothing changes (loops carry liveness round phis).
    for (int round = 0; round < 64; ++round) {
        changed_ = false;
        for (std::size_t k = insts_.size(); k-- > firstFunction_;) visit(insts_[k]);
        if (!changed_) break;
        if (round == 63) return false;
    }
    // A pointer into a uniform block may only be loaded from or indexed further.
    std::set<std::uint32_t> uniformPointers;
    for (std::size_t k = 0; k < insts_.size(); ++k) {
        const Inst& i = insts_[k];
        if (i.op == op::Variable && !i.lits.empty() && i.lits[0] == kStorageUniform) uniformPointers.insert(i.result);
        if ((i.op == op::AccessChain || i.op == op::InBoundsAccessChain) && !i.ids.empty() && uniformPointers.count(i.ids[0]))
            uniformPointers.insert(i.result);
    }
    for (std::size_t k = firstFunction_; k < insts_.size(); ++k) {
        const Inst& i = insts_[k];
        bool indexing = i.op == op::AccessChain || i.op == op::InBoundsAccessChain || i.op == op::Load;
        for (std::size_t j = 0; j < i.ids.size(); ++j)
            if (uniformPointers.count(i.ids[j]) && !(indexing && j == 0)) return false;
        if (i.op == op::Load && uniformPointers.count(i.ids[0]) && !uniformLoad(i)) return false;
    }
    return true;
}

// Byte offsets of each leaf of a value of `type` at `base` (a matrix's stride and majority come
// from the struct member that holds it; a matrix column's components are componentStride apart).
bool Analysis::leafBytes(std::uint32_t type, std::uint32_t base, std::uint32_t stride, bool rowMajor, std::uint32_t componentStride,
                         std::vector<std::pair<std::uint32_t, std::uint32_t>>& out, int depth) {
    const Inst* t = def(type);
    if (!t || out.size() > kMaxLeaves || depth > kMaxDepth) return false;
    switch (t->op) {
    case op::TypeBool:
    case op::TypeInt:
    case op::TypeFloat:
        out.push_back({base, t->lits.empty() ? 4 : t->lits[0] / 8});
        return true;
    case op::TypeVector: {
        const Inst* s = def(t->ids[0]);
        std::uint32_t width = s && !s->lits.empty() ? s->lits[0] / 8 : 4;
        std::uint32_t step = componentStride ? componentStride : width;
        for (std::uint32_t k = 0; k < t->lits[0]; ++k) out.push_back({base + k * step, width});
        return true;
    }
    case op::TypeMatrix:
        for (std::uint32_t c = 0; c < t->lits[0]; ++c)
            if (!leafBytes(t->ids[0], base + (rowMajor ? c * 4 : c * stride), 0, false, rowMajor ? stride : 0, out, depth + 1)) return false;
        return true;
    case op::TypeArray: {
        auto s = arrayStride_.find(type);
        auto length = constants_.find(t->ids[1]);
        if (s == arrayStride_.end() || length == constants_.end()) return false;
        for (std::uint32_t e = 0; e < length->second; ++e)
            if (!leafBytes(t->ids[0], base + e * s->second, stride, rowMajor, 0, out, depth + 1)) return false;
        return true;
    }
    case op::TypeStruct:
        for (std::uint32_t m = 0; m < t->ids.size(); ++m) {
            auto key = std::make_pair(type, m);
            auto offset = memberOffset_.find(key);
            if (offset == memberOffset_.end()) return false;
            std::uint32_t ms = matrixStride_.count(key) ? matrixStride_[key] : 16;
            if (!leafBytes(t->ids[m], base + offset->second, ms, rowMajor_.count(key) > 0, 0, out, depth + 1)) return false;
        }
        return true;
    default:
        return false;
    }
}

// A load from a uniform block: walks the access chains back to the block variable (a dynamic index
// takes every element), then records the bytes of the loaded value's live leaves.
bool Analysis::uniformLoad(const Inst& load) {
    std::vector<std::uint32_t> chain;  // index ids, outermost first
    std::uint32_t pointer = load.ids[0];
    const Inst* d = def(pointer);
    while (d && (d->op == op::AccessChain || d->op == op::InBoundsAccessChain)) {
        chain.insert(chain.begin(), d->ids.begin() + 1, d->ids.end());
        pointer = d->ids[0];
        d = def(pointer);
    }
    if (!d || d->op != op::Variable) return false;
    const Inst* pointerType = def(d->type);
    if (!pointerType || pointerType->ids.empty()) return false;
    const std::vector<char>& r = mask(load.result);
    bool any = false;
    for (char c : r) any = any || c;
    if (!any) return true;
    struct Step {
        std::uint32_t type, base, stride, componentStride;
        bool rowMajor;
    };
    std::vector<Step> at{{pointerType->ids[0], 0, 16, 0, false}};
    for (std::uint32_t index : chain) {
        std::vector<Step> next;
        for (const Step& s : at) {
            const Inst* t = def(s.type);
            if (!t || t->ids.empty()) return false;
            auto constant = constants_.find(index);
            if (t->op == op::TypeStruct) {
                if (constant == constants_.end() || constant->second >= t->ids.size()) return false;
                auto key = std::make_pair(s.type, constant->second);
                if (!memberOffset_.count(key)) return false;
                next.push_back({t->ids[constant->second], s.base + memberOffset_[key], matrixStride_.count(key) ? matrixStride_[key] : 16, 0,
                                rowMajor_.count(key) > 0});
                continue;
            }
            std::uint32_t count = 0, step = 0;
            Step inner = s;
            inner.type = t->ids[0];
            if (t->op == op::TypeArray) {
                if (!arrayStride_.count(s.type) || !constants_.count(t->ids[1])) return false;
                count = constants_[t->ids[1]], step = arrayStride_[s.type];
            } else if (t->op == op::TypeMatrix) {
                count = t->lits[0], step = s.rowMajor ? 4 : s.stride;
                inner.componentStride = s.rowMajor ? s.stride : 0;
            } else if (t->op == op::TypeVector) {
                count = t->lits[0], step = s.componentStride ? s.componentStride : 4;
            } else {
                return false;
            }
            if (constant != constants_.end()) {  // one element (past the end: none is read)
                inner.base = s.base + constant->second * step;
                if (constant->second < count) next.push_back(inner);
                continue;
            }
            for (std::uint32_t e = 0; e < count; ++e) {
                if (next.size() > kMaxLeaves) return false;
                Step one = inner;
                one.base = s.base + e * step;
                next.push_back(one);
            }
        }
        at = std::move(next);
    }
    for (const Step& s : at) {
        std::vector<std::pair<std::uint32_t, std::uint32_t>> offsets;
        const Inst* t = def(s.type);
        bool column = t && t->op == op::TypeVector && s.componentStride;
        if (!leafBytes(s.type, s.base, s.stride, s.rowMajor, column ? s.componentStride : 0, offsets)) return false;
        for (std::size_t k = 0; k < offsets.size() && k < r.size(); ++k)
            for (std::uint32_t b = 0; r[k] && b < offsets[k].second; b += 4) bytes_[pointer].insert(offsets[k].first + b);
    }
    return true;
}

std::map<std::uint32_t, std::vector<LiveRange>> Analysis::ranges() const {
    std::map<std::uint32_t, std::vector<LiveRange>> out;
    for (const auto& [variable, offsets] : bytes_) {
        std::vector<LiveRange>& list = out[variable];
        for (std::uint32_t b : offsets) {
            if (!list.empty() && std::uint32_t(list.back().offset + list.back().size) >= b) {
                list.back().size = std::max(list.back().size, int(b + 4) - list.back().offset);
                continue;
            }
            list.push_back({int(b), 4});
        }
    }
    return out;
}

}  // namespace

std::optional<std::map<std::uint32_t, std::vector<LiveRange>>> liveUniformBytes(const std::vector<std::uint32_t>& words) {
    Analysis a;
    if (!a.parse(words) || !a.run()) return std::nullopt;
    return a.ranges();
}

}  // namespace fxport::xlate
