// See sampler_textures.h.
#include "rewrite/sampler_textures.h"

#include <algorithm>
#include <set>
#include <vector>

#include "hlsl/call_arguments.h"
#include "fx/lexer.h"
#include "fx/text_util.h"

namespace fxport::xlate {

namespace {

// The texture object type a DX9 intrinsic samples: tex2D -> Texture2D; empty for others.
std::string textureTypeOf(const std::string& intrinsic) {
    if (intrinsic == "tex1D") return "Texture1D";
    if (intrinsic == "tex2D") return "Texture2D";
    if (intrinsic == "tex3D") return "Texture3D";
    if (intrinsic == "texCUBE") return "TextureCube";
    return {};
}

struct Edit {
    size_t begin, end;
    std::string text;
};

}  // namespace

std::string samplerTexturesDeclared(const std::string& text) {
    const std::vector<Token> t = tokenize(text);
    if (t.empty() || t[0].kind == Token::Kind::End) return text;
    // File-scope `sampler name` declarations (the DX9 keyword, untyped).
    std::set<std::string> samplers;
    int depth = 0;
    for (size_t i = 0; i + 1 < t.size() && t[i].kind != Token::Kind::End; ++i) {
        if (t[i].is("{")) ++depth;
        if (t[i].is("}")) --depth;
        const bool declarationStart = i == 0 || t[i - 1].is(";") || t[i - 1].is("}");
        if (depth != 0 || !declarationStart || !iequals(t[i].text, "sampler") || !t[i + 1].isIdent()) continue;
        samplers.insert(t[i + 1].text);
        // `sampler a, b = sampler_state { ... };` declares b too.
        int nesting = 0;
        for (size_t j = i + 2; j + 1 < t.size() && t[j].kind != Token::Kind::End && !(nesting == 0 && t[j].is(";")); ++j) {
            if (t[j].is("{") || t[j].is("(")) ++nesting;
            if (t[j].is("}") || t[j].is(")")) --nesting;
            if (nesting == 0 && t[j].is(",") && t[j + 1].isIdent()) samplers.insert(t[j + 1].text);
        }
    }
    // Those a method call samples with (`x.Sample(sam, ...)`, `x.SampleLevel(sam, ...)` ...).
    std::set<std::string> states;
    for (size_t i = 2; i + 2 < t.size(); ++i)
        if (t[i - 2].is(".") && t[i - 1].isIdent() && t[i].is("(") && samplers.count(t[i + 1].text) && (t[i + 2].is(",") || t[i + 2].is(")")))
            states.insert(t[i + 1].text);
    if (states.empty()) return text;
    std::vector<Edit> edits;
    std::vector<std::string> declared;  // "Texture2D sam_fxport_texture2D", first use first
    for (size_t i = 0; i + 3 < t.size() && t[i].kind != Token::Kind::End; ++i) {
        const std::string type = textureTypeOf(t[i].text);
        if (type.empty() || !t[i + 1].is("(") || (i > 0 && t[i - 1].is(".")) || !states.count(t[i + 2].text) || !t[i + 3].is(",")) continue;
        if (callArgumentSpans(t, i + 1, t.size()).size() != 2) continue;
        const std::string object = t[i + 2].text + "_fxport_" + toLower(type);
        const std::string declaration = type + " " + object + ";";
        if (std::find(declared.begin(), declared.end(), declaration) == declared.end()) declared.push_back(declaration);
        edits.push_back({t[i].offset, t[i + 1].end, object + ".Sample("});
    }
    if (edits.empty()) return text;
    std::string head;
    for (const auto& d : declared) head += d + " ";
    edits.insert(edits.begin(), {t[0].offset, t[0].offset, head});
    std::string out;
    size_t at = 0;
    for (const Edit& e : edits) {
        out.append(text, at, e.begin - at);
        out += e.text;
        at = e.end;
    }
    out.append(text, at, std::string::npos);
    return out;
}

}  // namespace fxport::xlate
