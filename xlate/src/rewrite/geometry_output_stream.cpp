// A geometry shader entry's output streams respelled for glslang (geometry_output_stream.h).
#include "rewrite/geometry_output_stream.h"

namespace fxport::xlate {

namespace {

// A stream object, or a struct holding one (fxc takes `inout struct S s[1]` holding a
// TriangleStream as the output at SM 5).
bool holdsStream(const EffectSyntax& syntax, const std::string& type, int depth = 0) {
    if (type.find("Stream<") != std::string::npos || type.find("Stream <") != std::string::npos) return true;
    const FxStruct* s = syntax.findStruct(syntax.resolveType(type));
    if (!s || depth > 8) return false;
    for (const auto& m : s->members)
        if (holdsStream(syntax, m.type, depth + 1)) return true;
    return false;
}

bool mentioned(const EffectSyntax& syntax, const FxFunction& f, const std::string& name) {
    for (size_t i = f.body.begin; i < f.body.end && i < syntax.tokens.size(); ++i)
        if (syntax.tokens[i].isIdent() && syntax.tokens[i].text == name && !(i > 0 && syntax.tokens[i - 1].is("."))) return true;
    return false;
}

}  // namespace

std::vector<TextEdit> geometryEntryOutputStreams(const EffectSyntax& syntax, const std::string& entry) {
    const FxFunction* f = syntax.findFunction(entry);
    if (!f || f->declaration.empty()) return {};
    const std::vector<Token>& t = syntax.tokens;
    size_t open = f->token + 1;
    if (open >= t.size() || !t[open].is("(")) return {};
    // The parameters' token ranges: commas at depth 0, `<...>` counted as brackets
    // (InputPatch<V, 3>).
    std::vector<std::pair<size_t, size_t>> ranges;
    size_t close = 0, start = open + 1;
    int depth = 0;
    for (size_t i = open; i < f->body.begin && i < t.size(); ++i) {
        if (t[i].is("(") || t[i].is("[") || t[i].is("<")) ++depth;
        else if (t[i].is(")") || t[i].is("]") || t[i].is(">")) {
            if (--depth == 0) {
                close = i;
                break;
            }
        } else if (depth == 1 && t[i].is(",")) {
            ranges.push_back({start, i});
            start = i + 1;
        }
    }
    if (close == 0) return {};
    if (start < close) ranges.push_back({start, close});
    if (ranges.size() != f->parameters.size()) return {};  // not the list the parser saw

    // Unused streams are blanked with the commas that would dangle; the rest of the list is left
    // as the other rewrites edit it.
    std::vector<bool> kept(ranges.size(), true);
    bool removed = false, streamKept = false;
    for (size_t k = 0; k < ranges.size(); ++k) {
        const FxParameter& p = f->parameters[k];
        // A struct holding a stream is fxc's to judge (geometry_entry_rules.cpp): left as it is.
        if (holdsStream(syntax, p.type) && p.type.find("Stream") == std::string::npos) return {};
        const bool stream = holdsStream(syntax, p.type);
        if (stream && !mentioned(syntax, *f, p.name)) {
            kept[k] = false;
            removed = true;
        } else {
            streamKept |= stream;
        }
    }
    if (!removed && streamKept) return {};
    std::vector<TextEdit> edits;
    bool anyKept = false;
    for (size_t k = 0; k < ranges.size(); ++k) {
        if (!kept[k] && ranges[k].second > ranges[k].first)
            edits.push_back({t[ranges[k].first].offset, t[ranges[k].second - 1].end, {}});
        // The comma after parameter k stays only between two kept parameters.
        anyKept |= kept[k];
        if (k + 1 < ranges.size() && !(anyKept && kept[k + 1])) {
            const Token& comma = t[ranges[k].second];
            edits.push_back({comma.offset, comma.end, {}});
        }
    }
    if (!streamKept) edits.push_back({t[close].offset, t[close].offset, std::string(anyKept ? ", " : "") + "inout PointStream<float4> fxport_noOutput"});
    return edits;
}

}  // namespace fxport::xlate
