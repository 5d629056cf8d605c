// A geometry shader's input clip/cull distances moved out of its input struct
// (geometry_clip_inputs.h).
#include "rewrite/geometry_clip_inputs.h"

#include <algorithm>
#include <cctype>

namespace fxport::xlate {

namespace {

// The kind ('c' clip, 'k' cull, 0 neither) and semantic index of a semantic.
std::pair<char, int> clipOrCull(const std::string& semantic) {
    std::string s;
    for (char c : semantic) s += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
    for (const auto& [prefix, kind] : {std::pair<std::string, char>{"SV_CLIPDISTANCE", 'c'}, {"SV_CULLDISTANCE", 'k'}}) {
        if (s.rfind(prefix, 0) != 0) continue;
        const std::string digits = s.substr(prefix.size());
        if (digits.empty()) return {kind, 0};
        if (digits.size() > 1 || !std::isdigit(static_cast<unsigned char>(digits[0]))) return {0, 0};
        return {kind, digits[0] - '0'};
    }
    return {0, 0};
}

bool isClipOrCull(const std::string& semantic) { return clipOrCull(semantic).first != 0; }

// Components of a clip/cull member's type (float, float1 .. float4), 0 for any other type.
int floatComponents(const std::string& type) {
    if (type == "float") return 1;
    if (type.size() == 6 && type.rfind("float", 0) == 0 && type[5] >= '1' && type[5] <= '4') return type[5] - '0';
    return 0;
}

// One register's worth of a clip/cull member: `to` (the struct member or array element to
// assign, after "input[v].") takes `count` components, in D3D's order of semantic index.
struct ClipPart {
    int semanticIndex = 0;
    std::string to;
    int count = 0;
    bool vector = false;
};

// The parts of member `m` (an array member takes one semantic index per element, as D3D does);
// false when its type is not a float scalar or vector, or it is an array of more than one rank.
bool clipParts(const FxStructMember& m, std::vector<ClipPart>& parts) {
    const int n = floatComponents(m.type);
    if (n == 0 || m.arrayDims.size() > 1) return false;
    const int base = clipOrCull(m.semantic).second;
    const bool vector = m.type != "float" && m.type != "float1";
    if (m.arrayDims.empty()) {
        parts.push_back({base, m.name, n, vector});
        return true;
    }
    for (int j = 0; j < m.arrayDims[0]; ++j) parts.push_back({base + j, m.name + "[" + std::to_string(j) + "]", n, vector});
    return true;
}

// `input[fxport_v].to = floatN(param[fxport_v][o], ...);` for each part, from offset 0 up.
std::string assembleParts(std::vector<ClipPart> parts, const std::string& input, const std::string& param) {
    std::stable_sort(parts.begin(), parts.end(), [](const ClipPart& a, const ClipPart& b) { return a.semanticIndex < b.semanticIndex; });
    std::string code;
    int offset = 0;
    for (const ClipPart& part : parts) {
        std::string value = part.vector ? "float" + std::to_string(part.count) + "(" : "";
        for (int c = 0; c < part.count; ++c)
            value += std::string(c ? ", " : "") + param + "[fxport_v][" + std::to_string(offset++) + "]";
        code += " " + input + "[fxport_v]." + part.to + " = " + value + (part.vector ? ")" : "") + ";";
    }
    return code;
}

int totalComponents(const std::vector<ClipPart>& parts) {
    int n = 0;
    for (const ClipPart& p : parts) n += p.count;
    return n;
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
        std::vector<ClipPart> clips, culls;
        bool known = true;
        for (const auto& m : s->members) {
            const char kind = clipOrCull(m.semantic).first;
            if (kind) {
                known &= clipParts(m, kind == 'c' ? clips : culls);
                continue;
            }
            std::string mods;
            for (const auto& mod : m.modifiers) mods += mod + " ";
            structs += " " + mods + m.type + " " + m.name + dims(m.arrayDims) + (m.semantic.empty() ? "" : " : " + m.semantic) + ";";
            assembly += " " + p.name + "[fxport_v]." + m.name + " = " + rest + "_" + p.name + "[fxport_v]." + m.name + ";";
        }
        if (!known) return {};
        // All clip distances as one arrayed input (and all cull distances as another), packed in
        // order of semantic index as the previous stage's outputs are (clip_distance_packing.h):
        // glslang mislays a second arrayed clip input, and it and SPIRV-Cross fail on an arrayed
        // float1 one.
        for (const auto& [parts, kind] : {std::pair{&clips, std::string("Clip")}, std::pair{&culls, std::string("Cull")}}) {
            if (parts->empty()) continue;
            const std::string param = "fxport_gs" + kind + "_" + p.name;
            params += ", " + prefix + "float " + param + "[" + n + "][" + std::to_string(totalComponents(*parts)) + "] : SV_" + kind + "Distance0";
            assembly += assembleParts(*parts, p.name, param);
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
