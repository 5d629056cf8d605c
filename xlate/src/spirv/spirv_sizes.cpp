// See spirv_sizes.h. Reads only the type, constant, name and variable instructions of the module
// (parsed by ParsedSpirv, parsed_spirv.h).
#include "spirv/spirv_sizes.h"

#include <algorithm>
#include <map>

#include "fx/input_limits.h"
#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

namespace {

// SPIR-V opcodes (the SPIR-V specification, 3.52).
enum : std::uint32_t {
    kOpName = 5,
    kOpMemberName = 6,
    kOpTypeBool = 20,
    kOpTypeInt = 21,
    kOpTypeFloat = 22,
    kOpTypeVector = 23,
    kOpTypeMatrix = 24,
    kOpTypeArray = 28,
    kOpTypeStruct = 30,
    kOpTypePointer = 32,
    kOpConstant = 43,
    kOpVariable = 59,
};
constexpr std::uint32_t kStorageInput = 1, kStorageOutput = 3;
constexpr std::uint64_t kSaturated = std::uint64_t{1} << 62;

std::uint64_t times(std::uint64_t a, std::uint64_t b) { return b != 0 && a > kSaturated / b ? kSaturated : a * b; }
std::uint64_t plus(std::uint64_t a, std::uint64_t b) { return std::min(kSaturated, a + b); }

struct Size {
    std::uint64_t bytes = 0, elements = 1;
};

std::string literalString(const std::uint32_t* words, std::uint32_t count) {
    std::string s;
    for (std::uint32_t i = 0; i < count; ++i)
        for (int b = 0; b < 4; ++b) {
            char c = static_cast<char>((words[i] >> (8 * b)) & 0xFF);
            if (c == '\0') return s;
            s += c;
        }
    return s;
}

class Module {
public:
    explicit Module(const ParsedSpirv& module) {
        for (const SpirvInstruction& i : module.instructions)
            instructions_.push_back({i.opcode(), std::vector<std::uint32_t>(i.words.begin() + 1, i.words.end())});
        for (const auto& [op, a] : instructions_) {
            if (op == kOpName && a.size() >= 2) names_[a[0]] = literalString(a.data() + 1, std::uint32_t(a.size() - 1));
            else if (op == kOpMemberName && a.size() >= 3) memberNames_[{a[0], a[1]}] = literalString(a.data() + 2, std::uint32_t(a.size() - 2));
            else if (op == kOpConstant && a.size() >= 3) constants_[a[1]] = a[2];
            else if (op >= kOpTypeBool && op <= kOpTypePointer && !a.empty()) types_[a[0]] = {op, a};
        }
    }

    std::optional<OversizedVariable> findOversized() {
        for (const auto& [op, a] : instructions_) {
            if (op != kOpVariable || a.size() < 3 || a[2] == kStorageInput || a[2] == kStorageOutput) continue;
            auto pointer = types_.find(a[0]);
            if (pointer == types_.end() || pointer->second.operands.size() < 3) continue;
            const std::uint32_t pointee = pointer->second.operands[2];
            // A constant buffer: each member is a global of the effect, checked (and named) apart.
            auto block = types_.find(pointee);
            if (block != types_.end() && block->second.op == kOpTypeStruct && (a[2] == 2 || a[2] == 0 || a[2] == 12)) {
                const std::vector<std::uint32_t> members(block->second.operands.begin() + 1, block->second.operands.end());
                std::uint32_t largest = 0;
                for (std::uint32_t m = 0; m < members.size(); ++m) {
                    if (auto over = check(members[m], memberName(pointee, m))) return over;
                    if (size(members[m], 0).bytes > size(members[largest], 0).bytes) largest = m;
                }
                if (Size whole = size(pointee, 0); whole.bytes > limits::kMaxVariableBytes) {
                    auto blockName = names_.find(pointee);
                    return OversizedVariable{memberName(pointee, largest), whole.bytes, whole.elements, 0,
                                             blockName == names_.end() ? std::string("$Global") : blockName->second};
                }
                continue;
            }
            auto name = names_.find(a[1]);
            if (auto over = check(pointee, name == names_.end() ? std::string() : name->second)) return over;
        }
        return std::nullopt;
    }

private:
    struct Instruction {
        std::uint32_t op;
        std::vector<std::uint32_t> operands;
    };

    std::string memberName(std::uint32_t type, std::uint32_t member) const {
        auto it = memberNames_.find({type, member});
        return it == memberNames_.end() ? std::string() : it->second;
    }

    std::optional<OversizedVariable> check(std::uint32_t type, const std::string& name) {
        Size s = size(type, 0);
        if (s.bytes <= limits::kMaxVariableBytes && s.elements <= std::uint64_t(limits::kMaxArrayElements)) return std::nullopt;
        std::uint64_t length = 0;
        if (auto it = types_.find(type); it != types_.end() && it->second.op == kOpTypeArray && it->second.operands.size() > 2)
            if (auto n = constants_.find(it->second.operands[2]); n != constants_.end()) length = n->second;
        return OversizedVariable{name, s.bytes, s.elements, length, std::string()};
    }

    Size size(std::uint32_t id, int depth) {
        if (auto it = sizes_.find(id); it != sizes_.end()) return it->second;
        Size s;
        auto it = types_.find(id);
        if (it == types_.end() || depth > 64) return s;  // images, samplers, ...: no storage here
        const auto& a = it->second.operands;
        switch (it->second.op) {
        case kOpTypeBool: s.bytes = 4; break;
        case kOpTypeInt:
        case kOpTypeFloat: s.bytes = a.size() > 1 ? std::max<std::uint32_t>(a[1] / 8, 1) : 4; break;
        case kOpTypeVector:
            if (a.size() > 2) s.bytes = times(size(a[1], depth + 1).bytes, a[2]);
            break;
        case kOpTypeMatrix:  // each column (HLSL: row) one 16-byte register
            if (a.size() > 2) s.bytes = times(std::max<std::uint64_t>(16, size(a[1], depth + 1).bytes), a[2]);
            break;
        case kOpTypeArray:
            if (a.size() > 2) {
                Size element = size(a[1], depth + 1);
                auto length = constants_.find(a[2]);
                std::uint64_t n = length == constants_.end() ? 1 : length->second;
                s.bytes = times((element.bytes + 15) / 16 * 16, n);
                s.elements = times(element.elements, n);
            }
            break;
        case kOpTypeStruct:
            for (size_t m = 1; m < a.size(); ++m) {
                Size member = size(a[m], depth + 1);
                s.bytes = plus(s.bytes, member.bytes);
                s.elements = std::max(s.elements, member.elements);
            }
            break;
        default: break;
        }
        sizes_[id] = s;
        return s;
    }

    std::vector<Instruction> instructions_;
    std::map<std::uint32_t, std::string> names_;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::string> memberNames_;
    std::map<std::uint32_t, std::uint32_t> constants_;
    std::map<std::uint32_t, Instruction> types_;
    std::map<std::uint32_t, Size> sizes_;
};

}  // namespace

std::optional<OversizedVariable> findOversizedVariable(const std::vector<std::uint32_t>& words) {
    ParsedSpirv module;
    if (!module.parse(words)) return std::nullopt;  // damaged (glslang's output never is): the validator says so
    return Module(module).findOversized();
}

}  // namespace fxport::xlate
