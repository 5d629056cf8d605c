// See object_array_dimensions.h.
#include "rewrite/object_array_dimensions.h"

#include <string>

namespace fxport::xlate {

namespace {

// The index one past the `]` closing the `[` at `open`; 0 when unbalanced before `end`.
size_t closing(const std::vector<Token>& t, size_t open, size_t end) {
    int depth = 0;
    for (size_t k = open; k < end; ++k) {
        if (t[k].is("[") || t[k].is("(")) ++depth;
        if ((t[k].is("]") || t[k].is(")")) && --depth == 0) return k + 1;
    }
    return 0;
}

std::string textOf(const std::vector<Token>& t, size_t begin, size_t end) {
    std::string s;
    for (size_t k = begin; k < end; ++k) s += (k > begin ? " " : "") + t[k].text;
    return s;
}

}  // namespace

std::vector<TextEdit> objectArraysFlattened(const EffectSyntax& syntax) {
    const auto& t = syntax.tokens;
    std::vector<TextEdit> edits;
    for (const FxTexture& tex : syntax.textures) {
        if (tex.dx9Object || tex.arrayDims.size() < 2) continue;
        long elements = 1;
        for (int d : tex.arrayDims) elements *= d > 0 ? d : 0;
        if (elements <= 0 || elements > 128) continue;
        // The declaration's dimensions: `[2][2]` after the name.
        size_t dims = tex.token + 1, dimsEnd = dims;
        for (size_t n = 0; n < tex.arrayDims.size() && t[dimsEnd].is("["); ++n) dimsEnd = closing(t, dimsEnd, t.size());
        if (dimsEnd == 0 || dimsEnd - dims != 3 * tex.arrayDims.size()) continue;
        std::vector<TextEdit> uses;
        bool flattenable = true;
        for (const FxFunction& f : syntax.functions) {
            for (size_t k = f.body.begin; k < f.body.end && flattenable; ++k) {
                if (!t[k].is(tex.name) || (k > 0 && t[k - 1].is("."))) continue;
                std::string index;
                size_t at = k + 1;
                for (size_t n = 0; n < tex.arrayDims.size(); ++n) {
                    const size_t close = t[at].is("[") ? closing(t, at, f.body.end) : 0;
                    if (close == 0) {
                        flattenable = false;  // the array, or part of it, as a value: left to glslang
                        break;
                    }
                    const std::string i = "(" + textOf(t, at + 1, close - 1) + ")";
                    index = n == 0 ? i : "(" + index + ") * " + std::to_string(tex.arrayDims[n]) + " + " + i;
                    at = close;
                }
                if (!flattenable) break;
                uses.push_back({t[k].offset, t[at - 1].end, tex.name + "[" + index + "]"});
                k = at - 1;
            }
        }
        if (!flattenable) continue;
        edits.push_back({t[dims].offset, t[dimsEnd - 1].end, "[" + std::to_string(elements) + "]"});
        edits.insert(edits.end(), uses.begin(), uses.end());
    }
    return edits;
}

}  // namespace fxport::xlate
