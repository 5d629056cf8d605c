// A reader's inputs moved to its writer's locations (see varying_links.h).
#include "fxport/xlate/varying_links.h"

#include <map>
#include <regex>
#include <set>

namespace fxport::xlate {

namespace {

// old location -> new one for the reader's inputs; empty when nothing moves.
std::map<int, int> moves(const std::vector<Varying>& inputs, const std::vector<Varying>& writerOutputs) {
    std::map<int, int> moved;
    std::set<int> taken;  // the locations the inputs end at
    std::vector<const Varying*> unmatched;
    for (const Varying& in : inputs) {
        const Varying* out = nullptr;
        for (const Varying& o : writerOutputs)
            if (o.semantic == in.semantic) out = &o;
        if (!out) {
            unmatched.push_back(&in);
            continue;
        }
        if (out->location != in.location) moved[in.location] = out->location;
        taken.insert(out->location);
    }
    if (moved.empty()) return moved;
    // Inputs nobody writes read undefined values in D3D too; they only must not collide.
    std::set<int> writerLocations;
    for (const Varying& o : writerOutputs) writerLocations.insert(o.location);
    for (const Varying* in : unmatched) {
        int location = in->location;
        if (taken.count(location)) {
            location = 31;
            while (location > 0 && (taken.count(location) || writerLocations.count(location))) --location;
            moved[in->location] = location;
        }
        taken.insert(location);
    }
    return moved;
}

}  // namespace

std::optional<CompiledShader> inputsLinkedTo(const CompiledShader& reader, const std::vector<Varying>& writerOutputs) {
    const std::map<int, int> moved = moves(reader.varyingInputs, writerOutputs);
    if (moved.empty()) return std::nullopt;
    // SPIRV-Cross declares each input on one line: `layout(location = 29) flat in vec4 in_var_X;`
    // (an array for a geometry shader's per-vertex inputs). Outputs and blocks are left alone.
    static const std::regex declaration(R"(layout\(location = (\d+)\)((?: \w+)*? in \w+ \w+(?:\[\d*\])*;))");
    std::string glsl;
    auto last = reader.glsl.cbegin();
    for (std::sregex_iterator it(reader.glsl.begin(), reader.glsl.end(), declaration), end; it != end; ++it) {
        const std::smatch& m = *it;
        glsl.append(last, m[0].first);
        const int location = std::stoi(m[1].str());
        auto move = moved.find(location);
        glsl += "layout(location = " + std::to_string(move == moved.end() ? location : move->second) + ")" + m[2].str();
        last = m[0].second;
    }
    glsl.append(last, reader.glsl.cend());
    CompiledShader linked = reader;
    linked.glsl = std::move(glsl);
    for (Varying& v : linked.varyingInputs)
        if (auto move = moved.find(v.location); move != moved.end()) v.location = move->second;
    return linked;
}

}  // namespace fxport::xlate
