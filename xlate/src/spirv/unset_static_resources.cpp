// See unset_static_resources.h.
#include "spirv/unset_static_resources.h"

#include <algorithm>
#include <cstring>
#include <map>
#include <regex>

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kOpTypeImage = 25, kOpTypeSampler = 26, kOpTypeSampledImage = 27, kOpTypeArray = 28,
                        kOpTypeRuntimeArray = 29, kOpTypePointer = 32, kOpVariable = 59, kOpLoad = 61, kOpStore = 62,
                        kOpCopyMemory = 63, kOpAccessChain = 65, kOpInBoundsAccessChain = 66, kStoragePrivate = 6,
                        kStorageFunction = 7;

bool isResourceType(const ParsedSpirv& m, std::uint32_t type, int depth = 0) {
    const SpirvInstruction* d = m.definition(type);
    if (!d || depth > 8) return false;
    switch (d->opcode()) {
    case kOpTypeImage:
    case kOpTypeSampler:
    case kOpTypeSampledImage: return true;
    case kOpTypeArray:
    case kOpTypeRuntimeArray: return isResourceType(m, d->word(2), depth + 1);
    default: return false;
    }
}

// The Private resource variables without an initializer: id -> whether read, whether written.
struct Use {
    bool read = false, written = false;
};

std::map<std::uint32_t, Use> unsetResourceVariables(const ParsedSpirv& m) {
    std::map<std::uint32_t, Use> out;
    for (const auto& inst : m.instructions) {
        if (inst.opcode() != kOpVariable || inst.words.size() != 4 || inst.word(3) != kStoragePrivate) continue;
        const SpirvInstruction* pointer = m.definition(inst.word(1));
        if (pointer && pointer->opcode() == kOpTypePointer && isResourceType(m, pointer->word(3))) out[inst.word(2)] = {};
    }
    return out;
}

// OpName of `id`, "(unnamed)" without one.
std::string nameOf(const ParsedSpirv& m, std::uint32_t id) {
    for (const auto& inst : m.instructions)
        if (inst.opcode() == spv_op::Name && inst.word(1) == id) {
            const auto* bytes = reinterpret_cast<const char*>(inst.words.data() + 2);
            return std::string(bytes, strnlen(bytes, (inst.words.size() - 2) * 4));
        }
    return "(unnamed)";
}

bool isIdentifier(const std::string& name) {
    return !name.empty() && name.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_") == std::string::npos;
}

int lineOfMatch(const std::string& source, const std::regex& declaration) {
    std::smatch m;
    if (!std::regex_search(source, m, declaration)) return 0;
    return 1 + int(std::count(source.begin(), source.begin() + m.position(0) + m.length(0), '\n'));
}

}  // namespace

std::string staticResourceReadWithoutValue(const std::vector<std::uint32_t>& words) {
    ParsedSpirv m;
    if (!m.parse(words)) return "";
    std::map<std::uint32_t, Use> vars = unsetResourceVariables(m);
    if (vars.empty()) return "";
    std::map<std::uint32_t, std::uint32_t> rootOf;  // access chain -> the variable it points into
    auto root = [&](std::uint32_t id) {
        auto chain = rootOf.find(id);
        return chain == rootOf.end() ? id : chain->second;
    };
    for (const auto& inst : m.instructions) {
        const std::uint32_t op = inst.opcode();
        if ((op == kOpAccessChain || op == kOpInBoundsAccessChain) && vars.count(root(inst.word(3)))) rootOf[inst.word(2)] = root(inst.word(3));
        if (op == kOpLoad && vars.count(root(inst.word(3)))) vars[root(inst.word(3))].read = true;
        if ((op == kOpStore || op == kOpCopyMemory) && vars.count(root(inst.word(1)))) vars[root(inst.word(1))].written = true;
        if (op == kOpCopyMemory && vars.count(root(inst.word(2)))) vars[root(inst.word(2))].read = true;
    }
    for (const auto& [id, use] : vars)
        if (use.read && !use.written) return nameOf(m, id);
    return "";
}

int staticDeclarationLine(const std::string& source, const std::string& name) {
    if (!isIdentifier(name)) return 0;
    return lineOfMatch(source, std::regex("\\bstatic\\b[^;{}()]*\\b" + name + "\\b"));
}

std::string localResourceVariableLeft(const std::vector<std::uint32_t>& words) {
    ParsedSpirv m;
    if (!m.parse(words)) return "";
    for (const auto& inst : m.instructions) {
        if (inst.opcode() != kOpVariable || inst.words.size() < 4 || inst.word(3) != kStorageFunction) continue;
        const SpirvInstruction* pointer = m.definition(inst.word(1));
        if (pointer && pointer->opcode() == kOpTypePointer && isResourceType(m, pointer->word(3))) return nameOf(m, inst.word(2));
    }
    return "";
}

// Whether offset `at` of `source` lies inside a function body: a `{` after `)` or after `) :
// SEMANTIC` opens one, and whatever it encloses is in it.
bool insideFunctionBody(const std::string& source, size_t at) {
    static const std::regex kBodyOpener(R"(\)\s*(:\s*\w+\s*)?$)");
    std::vector<bool> open;  // per enclosing `{`: a function body (or inside one)
    for (size_t i = 0; i < at && i < source.size(); ++i) {
        if (source[i] == '{') {
            const size_t from = i > 200 ? i - 200 : 0;
            open.push_back((!open.empty() && open.back()) || std::regex_search(source.substr(from, i - from), kBodyOpener));
        } else if (source[i] == '}' && !open.empty()) {
            open.pop_back();
        }
    }
    return !open.empty() && open.back();
}

int resourceDeclarationLine(const std::string& source, const std::string& name) {
    static const std::string kResourceType = "\\b(RW|RasterizerOrdered)?(Texture\\w*|\\w*Buffer|SamplerState|SamplerComparisonState|sampler\\w*)\\b\\s*(<[^>;]*>)?\\s+";
    if (isIdentifier(name)) return lineOfMatch(source, std::regex(kResourceType + "[^;{}()]*\\b" + name + "\\b"));
    // Unnamed (legalisation split the variable): the first local declaration of a resource.
    const std::regex local(kResourceType + "\\w+\\s*[\\[=;,]");
    for (auto it = std::sregex_iterator(source.begin(), source.end(), local); it != std::sregex_iterator(); ++it)
        if (insideFunctionBody(source, size_t(it->position(0))))
            return 1 + int(std::count(source.begin(), source.begin() + it->position(0), '\n'));
    return 0;
}

}  // namespace fxport::xlate
