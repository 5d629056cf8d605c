// fxc's rules for a geometry shader's input primitive and vertex count that glslang does not check
// (vkd3d's geometry-shader-syntax pins each):
//  - the entry carries [maxvertexcount(N)] with 1 <= N <= 1024;
//  - its input primitives (`triangle V v[3]`, `InputPatch<V, 3> p`) agree: one kind (primitive
//    arrays or InputPatch) and one vertex count;
//  - the primitive modifiers (point, line, triangle, lineadj, triangleadj) belong to the parameters
//    of a geometry shader's entry: not to globals, struct members, or vertex and pixel shader
//    parameters.
// The output stream rules are geometry_entry_rules.cpp's.
#include <algorithm>
#include <cstdlib>

#include "checks/fxc_checks.h"

namespace fxport::xlate {

namespace {

const char* primitiveModifier(const std::vector<std::string>& modifiers) {
    for (const char* m : {"point", "line", "triangle", "lineadj", "triangleadj"})
        if (std::find(modifiers.begin(), modifiers.end(), m) != modifiers.end()) return m;
    return nullptr;
}

// "InputPatch < V , 3 >" -> 3; -1 for other types.
long inputPatchSize(const std::string& type) {
    if (type.rfind("InputPatch", 0) != 0) return -1;
    size_t comma = type.rfind(',');
    return comma == std::string::npos ? -1 : std::strtol(type.c_str() + comma + 1, nullptr, 10);
}

class GeometryInputRules : public FxcCheck {
public:
    using FxcCheck::FxcCheck;

    void run() {
        for (const auto& g : syntax_.globals)
            if (const char* m = primitiveModifier(g.modifiers))
                report("'" + std::string(m) + "' on global '" + g.name + "': primitive modifiers belong to a geometry shader's input parameter", g.token);
        for (const auto& s : syntax_.structs)
            for (const auto& member : s.members)
                if (const char* m = primitiveModifier(member.modifiers))
                    report("'" + std::string(m) + "' on member '" + member.name + "' of struct '" + s.name +
                               "': primitive modifiers belong to a geometry shader's input parameter",
                           s.token);
        for (const auto& e : compiledEntries()) {
            if (e.profile.stage == ShaderStage::Geometry) geometryEntry(*e.function);
            else if (e.profile.stage == ShaderStage::Vertex || e.profile.stage == ShaderStage::Pixel) otherEntry(*e.function);
        }
    }

private:
    void otherEntry(const FxFunction& f) {
        for (const auto& p : f.parameters)
            if (const char* m = primitiveModifier(p.modifiers))
                report("'" + std::string(m) + "' on parameter '" + p.name + "' of '" + f.name + "': only a geometry shader takes an input primitive",
                       p.typeToken);
    }

    void geometryEntry(const FxFunction& f) {
        maxVertexCount(f);
        const FxParameter* first = nullptr;
        bool firstIsPatch = false;
        long firstCount = 0;
        for (const auto& p : f.parameters) {
            long patch = inputPatchSize(p.type);
            const char* primitive = primitiveModifier(p.modifiers);
            if (patch < 0 && !primitive) continue;
            long count = patch >= 0 ? patch : (p.arrayDims.empty() ? 1 : p.arrayDims[0]);
            if (!first) {
                first = &p;
                firstIsPatch = patch >= 0;
                firstCount = count;
                continue;
            }
            if ((patch >= 0) != firstIsPatch || count != firstCount)
                report("geometry shader input '" + p.name + "' of '" + f.name + "' is not the primitive '" + first->name +
                           "' is: every input primitive of a geometry shader has one kind and vertex count",
                       p.typeToken);
        }
    }

    void maxVertexCount(const FxFunction& f) {
        std::string attributes = f.attributes;  // as joined tokens: `[ maxvertexcount ( 4 ) ]`
        attributes.erase(std::remove(attributes.begin(), attributes.end(), ' '), attributes.end());
        std::string lower = attributes;
        std::transform(lower.begin(), lower.end(), lower.begin(), [](unsigned char c) { return char(std::tolower(c)); });
        size_t at = lower.find("maxvertexcount(");
        if (at == std::string::npos) {
            report("geometry shader '" + f.name + "' has no [maxvertexcount(N)] attribute", f.token);
            return;
        }
        char* end = nullptr;
        long count = std::strtol(attributes.c_str() + at + 15, &end, 10);
        if (end && *end == ')' && (count < 1 || count > 1024))
            report("maxvertexcount(" + std::to_string(count) + ") of '" + f.name + "' is outside 1..1024", f.token);
    }
};

}  // namespace

std::vector<std::pair<size_t, Diagnostic>> findGeometryInputErrors(const EffectSyntax& syntax, const SourceMap& map) {
    GeometryInputRules check(syntax, map);
    check.run();
    return check.takeFound();
}

}  // namespace fxport::xlate
