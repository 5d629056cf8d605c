// See sampler_array_elements.h.
#include "rewrite/sampler_array_elements.h"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <vector>

#include "fx/lexer.h"
#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

bool isSamplerType(const Token& t) {
    if (!t.isIdent()) return false;
    for (const char* s : {"sampler", "sampler1D", "sampler2D", "sampler3D", "samplerCUBE", "SamplerState", "SamplerComparisonState"})
        if (iequals(t.text, s)) return true;
    return false;
}

struct Edit {
    size_t begin, end;
    std::string text;
};

// One file-scope sampler array declaration the rewrite understands.
struct SamplerArray {
    std::string name;
    std::vector<long> dims;
    long elements = 1;
    int firstRegister = -1;                          // register(sN)
    std::vector<std::pair<size_t, size_t>> states;   // each element's initializer tokens [b, e)
    bool stateBlocks = false;                        // `sam[2] { {...}, {...} }` (no `=`)
    size_t nameToken = 0, end = 0;                   // end: the ';'
};

// The index of the '}' matching the '{' at `at`, or 0.
size_t closing(const std::vector<Token>& t, size_t at) {
    int depth = 0;
    for (size_t i = at; i < t.size() && t[i].kind != Token::Kind::End; ++i) {
        if (t[i].is("{")) ++depth;
        if (t[i].is("}") && --depth == 0) return i;
    }
    return 0;
}

// `{ item, item }` from `at` ('{'): the items' spans; each item is `sampler_state {...}` or `{...}`.
std::optional<std::vector<std::pair<size_t, size_t>>> initializerItems(const std::vector<Token>& t, size_t at, bool blocks) {
    std::vector<std::pair<size_t, size_t>> items;
    size_t i = at + 1;
    while (true) {
        const size_t begin = i;
        if (!blocks) {
            if (!iequals(t[i].text, "sampler_state")) return std::nullopt;
            ++i;
        }
        if (!t[i].is("{")) return std::nullopt;
        const size_t close = closing(t, i);
        if (!close) return std::nullopt;
        items.push_back({begin, close + 1});
        i = close + 1;
        if (t[i].is(",")) {
            ++i;
            continue;
        }
        if (!t[i].is("}")) return std::nullopt;
        return items;
    }
}

std::optional<SamplerArray> declaration(const std::vector<Token>& t, size_t at) {
    SamplerArray a;
    a.nameToken = at;
    a.name = t[at].text;
    size_t i = at + 1;
    while (t[i].is("[")) {
        if (t[i + 1].kind != Token::Kind::Number || !t[i + 2].is("]")) return std::nullopt;
        const long n = std::atol(t[i + 1].text.c_str());
        if (n <= 0 || n > 64) return std::nullopt;
        a.dims.push_back(n);
        a.elements *= n;
        i += 3;
    }
    if (a.elements > 64) return std::nullopt;
    if (t[i].is(":")) {
        const std::string& r = t[i + 3].text;
        if (!iequals(t[i + 1].text, "register") || !t[i + 2].is("(") || !t[i + 4].is(")") || r.size() < 2 ||
            (r[0] != 's' && r[0] != 'S') || r.find_first_not_of("0123456789", 1) != std::string::npos)
            return std::nullopt;
        a.firstRegister = std::atoi(r.c_str() + 1);
        i += 5;
    }
    if (t[i].is("=") || t[i].is("{")) {
        a.stateBlocks = t[i].is("{");
        const size_t open = a.stateBlocks ? i : i + 1;
        if (!t[open].is("{")) return std::nullopt;
        auto items = initializerItems(t, open, a.stateBlocks);
        if (!items || long(items->size()) != a.elements) return std::nullopt;
        a.states = *items;
        i = closing(t, open) + 1;
    }
    if (!t[i].is(";")) return std::nullopt;
    a.end = i;
    return a;
}

// Every other mention of the array is `name[i][j]` with literal indices: the edits naming elements.
// None when DX9 intrinsics sample its elements with different dimensions (tex2D and tex3D): fxc
// refuses that at SM4+ and FX1404 stands for its error (SM2-3 would take it).
std::optional<std::vector<Edit>> elementUses(const std::vector<Token>& t, const SamplerArray& a) {
    std::vector<Edit> edits;
    std::vector<char> dimensions;
    for (size_t i = 0; i < t.size() && t[i].kind != Token::Kind::End; ++i) {
        if (i == a.nameToken || !t[i].isIdent() || t[i].text != a.name) continue;
        if (i > 0 && (t[i - 1].is(".") || t[i - 1].is("::"))) continue;  // a member of that name
        long flat = 0;
        size_t k = i + 1;
        for (long n : a.dims) {
            if (!t[k].is("[") || t[k + 1].kind != Token::Kind::Number || !t[k + 2].is("]")) return std::nullopt;
            const long index = std::atol(t[k + 1].text.c_str());
            if (index < 0 || index >= n) return std::nullopt;
            flat = flat * n + index;
            k += 3;
        }
        edits.push_back({t[i].offset, t[k - 1].end, a.name + "_fxport_" + std::to_string(flat)});
        // The dimension a DX9 intrinsic samples this element with (tex1D and tex2D are one).
        if (i >= 2 && t[i - 1].is("(") && t[i - 2].isIdent()) {
            const std::string& f = t[i - 2].text;
            const char dimension = f.rfind("tex3D", 0) == 0 ? '3' : f.rfind("texCUBE", 0) == 0 ? 'c' : f.rfind("tex", 0) == 0 ? '2' : 0;
            if (dimension && !dimensions.empty() && dimensions.back() != dimension) return std::nullopt;
            if (dimension) dimensions.push_back(dimension);
        }
    }
    return edits;
}

std::string slice(const std::string& text, const std::vector<Token>& t, std::pair<size_t, size_t> span) {
    return text.substr(t[span.first].offset, t[span.second - 1].end - t[span.first].offset);
}

// `sam_fxport_0 : register(s3) = sampler_state {...}, sam_fxport_1 ...;` for the whole declaration
// after its type.
std::string elementDeclarations(const std::string& text, const std::vector<Token>& t, const SamplerArray& a) {
    std::string out;
    for (long k = 0; k < a.elements; ++k) {
        if (k) out += ", ";
        out += a.name + "_fxport_" + std::to_string(k);
        if (a.firstRegister >= 0) out += " : register(s" + std::to_string(a.firstRegister + k) + ")";
        if (!a.states.empty()) {
            std::string state = slice(text, t, a.states[size_t(k)]);
            std::replace(state.begin(), state.end(), '\n', ' ');
            out += (a.stateBlocks ? " " : " = ") + state;
        }
    }
    return out + ";";
}

}  // namespace

std::string samplerArraysAsElements(const std::string& text) {
    const std::vector<Token> t = tokenize(text);
    std::vector<Edit> edits;
    int depth = 0;
    for (size_t i = 0; i + 3 < t.size() && t[i].kind != Token::Kind::End; ++i) {
        if (t[i].is("{")) ++depth;
        if (t[i].is("}")) --depth;
        const bool declarationStart = i == 0 || t[i - 1].is(";") || t[i - 1].is("}");
        if (depth != 0 || !declarationStart || !isSamplerType(t[i]) || !t[i + 1].isIdent() || !t[i + 2].is("[")) continue;
        auto a = declaration(t, i + 1);
        if (!a) continue;
        auto uses = elementUses(t, *a);
        if (!uses) continue;
        edits.push_back({t[i + 1].offset, t[a->end].end, elementDeclarations(text, t, *a)});
        edits.insert(edits.end(), uses->begin(), uses->end());
        i = a->end;
    }
    if (edits.empty()) return text;
    std::sort(edits.begin(), edits.end(), [](const Edit& x, const Edit& y) { return x.begin < y.begin; });
    std::string out;
    size_t at = 0;
    for (const Edit& e : edits) {
        if (e.begin < at) continue;
        out.append(text, at, e.begin - at);
        out += e.text;
        // The original's line breaks stay, so every later line keeps its number.
        out.append(size_t(std::count(text.begin() + long(e.begin), text.begin() + long(e.end), '\n')), '\n');
        at = e.end;
    }
    out.append(text, at, std::string::npos);
    return out;
}

}  // namespace fxport::xlate
