// fxc's rules for a geometry shader's entry function and its output streams that glslang does not
// check (vkd3d's geometry-shader-syntax pins each):
//  - an output stream parameter is `inout` and not an array of more than one stream;
//  - the entry returns void and has no `out` parameter besides its streams;
//  - a stream object (or a struct holding one) is never a global variable;
//  - SM 4 writes one stream, the first; SM 5 up to four, and only point streams when it writes
//    more than one (a stream the shader never mentions is not validated);
//  - maxvertexcount times the output's components (packed as fxc packs a signature, over every
//    stream written) is at most 1024.
#include <algorithm>
#include <array>
#include <cstdlib>

#include "checks/fxc_checks.h"
#include "hlsl/hlsl_types.h"

namespace fxport::xlate {

namespace {

// "TriangleStream < gs_data >" -> "TriangleStream"; empty for other types.
std::string streamKind(const std::string& type) {
    std::string head = type.substr(0, type.find('<'));
    while (!head.empty() && head.back() == ' ') head.pop_back();
    return head == "PointStream" || head == "LineStream" || head == "TriangleStream" ? head : std::string();
}

std::string streamElement(const std::string& type) {
    size_t open = type.find('<'), close = type.rfind('>');
    if (open == std::string::npos || close == std::string::npos || close < open) return {};
    std::string e = type.substr(open + 1, close - open - 1);
    e.erase(std::remove(e.begin(), e.end(), ' '), e.end());
    return e;
}

class GeometryEntryRules : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        globalStreams();
        for (const auto& e : compiledEntries()) {
            if (e.profile.stage != ShaderStage::Geometry) continue;
            entry(*e.function, e.profile);
        }
    }

private:
    struct Stream {
        const FxParameter* parameter;
        size_t index;
    };

    bool holdsStream(const std::string& type, int depth = 0) const {
        if (!streamKind(type).empty()) return true;
        const FxStruct* s = syntax_.findStruct(syntax_.resolveType(type));
        if (!s || depth > 8) return false;
        for (const auto& m : s->members)
            if (holdsStream(m.type, depth + 1)) return true;
        return false;
    }

    void globalStreams() {
        for (const auto& g : syntax_.globals)
            if (holdsStream(g.type))
                report("'" + g.name + "' holds a stream output object: streams are only parameters of a geometry shader's entry, never global variables", g.token);
    }

    void entry(const FxFunction& f, const ShaderProfile& profile) {
        if (f.returnType != "void")
            report("a geometry shader's entry '" + f.name + "' must return void; it writes its vertices to an output stream", f.token);
        std::vector<Stream> streams;
        for (const auto& p : f.parameters) {
            bool isStream = !streamKind(p.type).empty();
            bool inout = std::find(p.modifiers.begin(), p.modifiers.end(), "inout") != p.modifiers.end();
            bool out = std::find(p.modifiers.begin(), p.modifiers.end(), "out") != p.modifiers.end();
            if (isStream) {
                if (!inout) report("output stream '" + p.name + "' must be declared inout", p.typeToken);
                else if (!p.arrayDims.empty() && p.arrayDims[0] != 1)
                    report("output stream '" + p.name + "' is an array: a geometry shader takes each stream as its own parameter", p.typeToken);
                streams.push_back({&p, streams.size()});
            } else if (out || (inout && !holdsStream(p.type))) {
                report("'" + p.name + "' is an out parameter of geometry shader '" + f.name + "': its outputs go through the output stream", p.typeToken);
            }
        }
        std::vector<Stream> used;
        for (const auto& s : streams)
            if (mentionedIn({&f}, s.parameter->name)) used.push_back(s);
        for (const auto& s : used) {
            if (profile.major < 5 && s.index > 0)
                report("'" + s.parameter->name + "' is output stream " + std::to_string(s.index) + ": SM 4 writes the first stream only", s.parameter->typeToken);
            else if (s.index >= 4)
                report("'" + s.parameter->name + "' is output stream " + std::to_string(s.index) + ": D3D has 4 streams", s.parameter->typeToken);
            else if (used.size() > 1 && streamKind(s.parameter->type) != "PointStream")
                report("'" + s.parameter->name + "' is a " + streamKind(s.parameter->type) + ": a shader writing several streams writes point streams only",
                       s.parameter->typeToken);
        }
        maxVertexCount(f, used);
    }

    // --- maxvertexcount x output components <= 1024 ------------------------------------------------
    void maxVertexCount(const FxFunction& f, const std::vector<Stream>& used) {
        std::string attributes = f.attributes;  // as joined tokens: `[ maxvertexcount ( 4 ) ]`
        attributes.erase(std::remove(attributes.begin(), attributes.end(), ' '), attributes.end());
        size_t at = attributes.find("maxvertexcount(");
        if (at == std::string::npos || used.empty()) return;
        long count = std::strtol(attributes.c_str() + at + 15, nullptr, 10);
        std::vector<std::array<bool, 4>> registers;  // the union of every written stream's packing
        for (const auto& s : used) {
            std::vector<int> widths;
            if (!flatten(streamElement(s.parameter->type), widths, 0)) return;  // a type not judged
            std::vector<int> filled;
            for (int w : widths) {
                size_t r = 0;
                while (r < filled.size() && filled[r] + w > 4) ++r;
                if (r == filled.size()) filled.push_back(0);
                if (registers.size() <= r) registers.resize(r + 1, {false, false, false, false});
                for (int c = filled[r]; c < filled[r] + w; ++c) registers[r][c] = true;
                filled[r] += w;
            }
        }
        long components = 0;
        for (const auto& r : registers) components += std::count(r.begin(), r.end(), true);
        if (count * components > 1024)
            report("maxvertexcount(" + std::to_string(count) + ") times " + std::to_string(components) +
                       " output components is more than the 1024 a geometry shader may emit",
                   f.token);
    }
    // The component widths of each register-sized piece of `type` (a vector, a matrix row, an array
    // element, struct members in order); false for what is not numbers.
    bool flatten(const std::string& typeName, std::vector<int>& widths, int depth) const {
        std::string type = syntax_.resolveType(typeName);
        BasicType b = describeBasicType(type);
        if (b.ok) {
            for (int r = 0; r < b.rows; ++r) widths.push_back(b.columns);
            return true;
        }
        const FxStruct* s = syntax_.findStruct(type);
        if (!s || depth > 8) return false;
        for (const auto& m : s->members) {
            long long count = 1;  // capped: a stream element past 1024 components is not judged
            for (int d : m.arrayDims) count = std::min(count * std::max(d, 1), 1LL << 20);
            if (count > 1024) return false;
            for (long long k = 0; k < count; ++k)
                if (!flatten(m.type, widths, depth + 1)) return false;
        }
        return true;
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findGeometryEntryErrors(const EffectSyntax& syntax, const SourceMap& map) {
    GeometryEntryRules check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
