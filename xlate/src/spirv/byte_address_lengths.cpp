// See byte_address_lengths.h: ByteAddressBuffer.GetDimensions reports bytes, as on D3D.
#include "spirv/byte_address_lengths.h"

#include <regex>

namespace fxport::xlate {

namespace {

constexpr std::uint32_t kOpVariable = 59, kOpArrayLength = 68, kOpIMul = 132;

// The literal string of an OpName (words from index 2, NUL-terminated, little-endian bytes).
std::string nameOf(const SpirvInstruction& name) {
    std::string s;
    for (size_t k = 2; k < name.words.size(); ++k)
        for (int b = 0; b < 4; ++b) {
            const char c = char((name.words[k] >> (8 * b)) & 0xFFu);
            if (c == '\0') return s;
            s += c;
        }
    return s;
}

// The global variables of `m` whose debug name is in `names`.
std::set<std::uint32_t> namedVariables(const ParsedSpirv& m, const std::set<std::string>& names) {
    std::set<std::uint32_t> ids;
    for (const auto& in : m.instructions) {
        if (in.opcode() != spv_op::Name || in.words.size() < 3 || !names.count(nameOf(in))) continue;
        const SpirvInstruction* d = m.definition(in.words[1]);
        if (d && d->opcode() == kOpVariable) ids.insert(in.words[1]);
    }
    return ids;
}

}  // namespace

std::set<std::string> byteAddressBufferNames(const std::string& hlsl) {
    static const std::regex declaration(R"(\b(?:RW)?ByteAddressBuffer\s+([A-Za-z_]\w*))");
    std::set<std::string> names;
    for (std::sregex_iterator it(hlsl.begin(), hlsl.end(), declaration), end; it != end; ++it)
        names.insert((*it)[1].str());
    return names;
}

bool byteAddressLengthsInBytes(ParsedSpirv& m, const std::set<std::string>& names) {
    if (names.empty() || !m.has({kOpArrayLength})) return false;
    const std::set<std::uint32_t> buffers = namedVariables(m, names);
    if (buffers.empty()) return false;
    bool changed = false;
    m.rewrite([&](const SpirvInstruction& in, std::vector<SpirvInstruction>& out) {
        // %r = OpArrayLength %uint %buffer member  ->  %words = OpArrayLength ...; %r = OpIMul %uint %words 4
        const auto& w = in.words;
        if (in.opcode() != kOpArrayLength || w.size() != 5 || !buffers.count(w[3])) return out.push_back(in);
        const std::uint32_t words = m.newId();
        out.push_back({{spirvFirstWord(kOpArrayLength, 5), w[1], words, w[3], w[4]}});
        out.push_back({{spirvFirstWord(kOpIMul, 5), w[1], w[2], words, m.constant(w[1], 4)}});
        changed = true;
    });
    return changed;
}

}  // namespace fxport::xlate
