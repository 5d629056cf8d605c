// A geometry shader's input clip/cull distances moved out of its input struct
// (geometry_clip_inputs.h).
#include "rewrite/geometry_clip_inputs.h"

#include <cctype>

namespace fxport::xlate {

namespace {

bool isClipOrCull(const std::string& semantic) {
    std::string s;
    for (char c : semantic) s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    return s.rfind("SV_CLIPDISTANCE", 0) == 0 || s.rfind("SV_CULLDISTANCE", 0) == 0;
}

std::string dims(const std::vector<int>& arrayDims) {
    std::string s;
    for (int d : arrayDims) s += "[" + std::to_string(d) + "]";
    return s;
}

// The token ranges of the entry's parameters (commas at depth 0, `<...>` counted as brackets);
// empty when the list is not the one the parser saw.
std::vector<std::pair<size_t, size_t>> parameterRanges(const EffectSyntax& syntax, const FxFunction& f) {
    const std::vector<Token>& t = syntax.tokens;
    std::vector<std::pair<size_t, size_t>> ranges;
    size_t open = f.token + 1, start = open + 1;
    if (open >= t.size() || !t[open].is("(")) return {};
    int depth = 0;
    for (size_t i = open; i < f.body.begin && i < t.size(); ++i) {
        if (t[i].is("(") || t[i].is("[") || t[i].is("<")) {
            ++depth;
        } else if (t[i].is(")") || t[i].is("]") || t[i].is(">")) {
            if (--depth == 0) {
                if (start < i) ranges.push_back({start, i});
                return ranges.size() == f.parameters.size() ? ranges : std::vector<std::pair<size_t, size_t>>{};
            }
        } else if (depth == 1 && t[i].is(",")) {
            ranges.push_back({start, i});
            start = i + 1;
        }
    }
    return {};
}

}  // namespace

std::vector<TextEdit> geometryEntryClipInputs(const EffectSyntax& syntax, const std::string& entry) {
    const FxFunction* f = syntax.findFunction(entry);
    if (!f || f->declaration.empty() || f->body.begin == 0) return {};
    std::vector<std::pair<size_t, size_t>> ranges = parameterRanges(syntax, *f);
    std::vector<TextEdit> edits;
    std::string structs, assembly;
    for (size_t k = 0; k < ranges.size(); ++k) {
        const FxParameter& p = f->parameters[k];
        const FxStruct* s = syntax.findStruct(syntax.resolveType(p.type));
        if (!s || p.arrayDims.size() != 1) continue;
        bool clip = false;
        for (const auto& m : s->members) clip |= isClipOrCull(m.semantic);
        if (!clip) continue;
        std::string prefix;  // the primitive (triangle, point ...) and any other modifier
        for (const auto& m : p.modifiers) prefix += m + " ";
        const std::string n = std::to_string(p.arrayDims[0]);
        const std::string rest = "fxport_gsin_" + s->name;
        std::string params = prefix + rest + " " + rest + "_" + p.name + "[" + n + "]";
        structs += "struct " + rest + " {";
        assembly += " " + s->name + " " + p.name + "[" + n + "]; for (int fxport_v = 0; fxport_v < " + n + "; ++fxport_v) {";
        for (const auto& m : s->members) {
            std::string to = " " + p.name + "[fxport_v]." + m.name + " = ";
            if (isClipOrCull(m.semantic)) {
                std::string param = "fxport_gsclip_" + p.name + "_" + m.name;
                // A scalar gets an inner [1]: as a plain float[n] SPIRV-Cross sizes gl_in's
                // gl_ClipDistance n, not the 1 the previous stage writes, and GL refuses the link.
                const bool scalar = m.type == "float" && m.arrayDims.empty();
                params += ", " + prefix + m.type + " " + param + "[" + n + "]" + (scalar ? "[1]" : dims(m.arrayDims)) + " : " + m.semantic;
                assembly += to + param + "[fxport_v]" + (scalar ? "[0];" : ";");
                continue;
            }
            std::string mods;
            for (const auto& mod : m.modifiers) mods += mod + " ";
            structs += " " + mods + m.type + " " + m.name + dims(m.arrayDims) + (m.semantic.empty() ? "" : " : " + m.semantic) + ";";
            assembly += to + rest + "_" + p.name + "[fxport_v]." + m.name + ";";
        }
        structs += " }; ";
        assembly += " }";
        const std::vector<Token>& t = syntax.tokens;
        edits.push_back({t[ranges[k].first].offset, t[ranges[k].second - 1].end, params});
    }
    if (edits.empty()) return {};
    const std::vector<Token>& t = syntax.tokens;
    size_t at = t[f->declaration.begin].offset;
    edits.push_back({at, at, structs});
    size_t brace = t[f->body.begin - 1].end;
    edits.push_back({brace, brace, assembly});
    return edits;
}

}  // namespace fxport::xlate
