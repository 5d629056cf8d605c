// See keyword_identifiers.h.
#include "rewrite/keyword_identifiers.h"

#include <cstring>
#include <string>

namespace fxport::xlate {

namespace {

const std::string kPrefix = "fxport_kw_";

// A modifier where a type or another modifier follows (`precise float4 v;`, `precise out float x`);
// a name anywhere else (`float4 precise;`, `precise.x`, `(precise)`). Once the effect declares
// `typedef float4 precise;`, `precise main()` and `precise v;` use that type: one name, then the
// end of a declarator, follows (a modifier is followed by a type and then a name).
bool isNameUse(const std::vector<Token>& t, size_t i, bool typedefNamed) {
    if (!t[i + 1].isIdent()) return true;
    if (!typedefNamed || i + 2 >= t.size()) return false;
    const Token& after = t[i + 2];
    return after.is("(") || after.is(";") || after.is(",") || after.is("=") || after.is(":") || after.is("[") || after.is(")");
}

// `typedef ... precise;`: the effect names a type `precise`.
bool typedefNamesPrecise(const std::vector<Token>& t) {
    for (size_t i = 0; i + 1 < t.size(); ++i)
        if (t[i].is("precise") && t[i + 1].is(";"))
            for (size_t k = i; k-- > 0 && !t[k].is(";") && !t[k].is("}") && !t[k].is("{");)
                if (t[k].is("typedef")) return true;
    return false;
}

// glslang reserves the SM 5.1 template types' names; fxc up to SM 5.0 reads them as names, and the
// DirectX SDK's tutorials declare `cbuffer ConstantBuffer : register(b0)`. A use with a template
// argument list stays the type.
bool isTemplateTypeName(const std::vector<Token>& t, size_t i) {
    return (t[i].is("ConstantBuffer") || t[i].is("TextureBuffer")) && !t[i + 1].is("<");
}

std::string literalString(const std::uint32_t* w, size_t count) {
    std::string s(reinterpret_cast<const char*>(w), count * 4);
    return s.substr(0, std::strlen(s.c_str()));
}

// SPIR-V's literal string: UTF-8 bytes, the first in a word's lowest byte, NUL-terminated and padded.
// (Packed byte by byte: GCC 12 -O3 sees a bogus overflow in a memcpy of s.size() bytes.)
void appendString(std::vector<std::uint32_t>& out, const std::string& s) {
    for (size_t w = 0; w < s.size() / 4 + 1; ++w) {
        std::uint32_t word = 0;
        for (size_t b = 0; b < 4 && w * 4 + b < s.size(); ++b)
            word |= std::uint32_t(static_cast<unsigned char>(s[w * 4 + b])) << (8 * b);
        out.push_back(word);
    }
}

}  // namespace

std::vector<TextEdit> keywordIdentifiersRenamed(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    const bool typedefNamed = typedefNamesPrecise(t);
    for (size_t i = 0; i + 1 < t.size(); ++i)
        if (t[i].isIdent() && ((t[i].is("precise") && isNameUse(t, i, typedefNamed)) || isTemplateTypeName(t, i)))
            edits.push_back({t[i].offset, t[i].end, kPrefix + t[i].text});
    return edits;
}

std::string keywordIdentifierSpelled(const std::string& type) { return type == "precise" ? kPrefix + type : type; }

bool restoreKeywordIdentifiers(ParsedSpirv& m) {
    bool changed = false;
    for (SpirvInstruction& inst : m.instructions) {
        const std::uint32_t op = inst.opcode();
        const size_t fixed = op == spv_op::Name ? 2 : op == spv_op::MemberName ? 3 : 0;  // words before the string
        if (!fixed || inst.words.size() <= fixed) continue;
        std::string name = literalString(&inst.words[fixed], inst.words.size() - fixed);
        if (name.rfind(kPrefix, 0) != 0) continue;
        std::vector<std::uint32_t> words(inst.words.begin(), inst.words.begin() + std::ptrdiff_t(fixed));
        appendString(words, name.substr(kPrefix.size()));
        words[0] = spirvFirstWord(op, words.size());
        inst.words = std::move(words);
        changed = true;
    }
    return changed;
}

}  // namespace fxport::xlate
