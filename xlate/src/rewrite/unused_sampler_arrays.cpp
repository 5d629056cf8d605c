// See unused_sampler_arrays.h.
#include "rewrite/unused_sampler_arrays.h"

#include <cstdlib>
#include <map>
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

// `name[N][M] ;` or `name[N][M] { {...}, ... };` from `at` (the name): the index of ';' when the
// declaration is one fxc takes, else 0. A state-block list holds one block per element, blocks
// nest no deeper and no comma trails (fxc's errors otherwise, which FX1404 then stands for); an
// array of one element may take its block without the list.
size_t declarationEnd(const std::vector<Token>& t, size_t at) {
    size_t i = at + 1;
    long elements = 1;
    while (t[i].is("[")) {
        if (t[i + 1].kind != Token::Kind::Number || !t[i + 2].is("]")) return 0;
        elements *= std::atol(t[i + 1].text.c_str());
        if (elements <= 0 || elements > 65536) return 0;
        i += 3;
    }
    if (t[i].is(";")) return i;
    if (!t[i].is("{")) return 0;
    if (elements == 1 && !t[i + 1].is("{")) {  // one element: its block alone, without the list
        for (++i; !t[i].is("}"); ++i)
            if (t[i].is("{") || t[i].kind == Token::Kind::End) return 0;
        return t[i + 1].is(";") ? i + 1 : 0;
    }
    long blocks = 0;
    for (++i;; ++i) {
        if (!t[i].is("{")) return 0;
        for (++i; !t[i].is("}"); ++i)
            if (t[i].is("{") || t[i].kind == Token::Kind::End) return 0;
        ++blocks;
        if (t[i + 1].is(",") && !t[i + 2].is("}")) {
            ++i;
            continue;
        }
        if (!t[i + 1].is("}") || !t[i + 2].is(";")) return 0;
        return blocks == elements ? i + 2 : 0;
    }
}

}  // namespace

std::string dropUnusedSamplerArrays(const std::string& text) {
    const std::vector<Token> t = tokenize(text);
    std::map<std::string, int> mentions;
    for (const Token& tok : t)
        if (tok.isIdent()) ++mentions[tok.text];
    std::string out = text;
    int depth = 0;
    bool changed = false;
    for (size_t i = 0; i + 3 < t.size() && t[i].kind != Token::Kind::End; ++i) {
        if (t[i].is("{")) ++depth;
        if (t[i].is("}")) --depth;
        const bool declarationStart = i == 0 || t[i - 1].is(";") || t[i - 1].is("}");
        if (depth != 0 || !declarationStart || !isSamplerType(t[i]) || !t[i + 1].isIdent() || !t[i + 2].is("[")) continue;
        if (mentions[t[i + 1].text] != 1) continue;
        const size_t end = declarationEnd(t, i + 1);
        if (end == 0) continue;
        for (size_t k = t[i].offset; k < t[end].end; ++k)
            if (out[k] != '\n') out[k] = ' ';
        changed = true;
        i = end;
    }
    return changed ? out : text;
}

}  // namespace fxport::xlate
