// A geometry shader's doubly indexed clip/cull reads respelled through gl_in (arrayed_clip_inputs.h).
#include "glsl/arrayed_clip_inputs.h"

#include <cctype>
#include <regex>

namespace fxport::xlate {

namespace {

bool identifierChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.'; }

// The index after position `open` (a '['), bracket-matched; npos past the end when unbalanced.
size_t matchingBracket(const std::string& s, size_t open) {
    int depth = 0;
    for (size_t i = open; i < s.size(); ++i) {
        if (s[i] == '[') ++depth;
        else if (s[i] == ']' && --depth == 0) return i;
    }
    return std::string::npos;
}

std::string respell(const std::string& glsl, const std::string& name) {
    std::string out;
    size_t at = 0;
    for (size_t p = glsl.find(name + "["); p != std::string::npos; p = glsl.find(name + "[", p + 1)) {
        if (p > 0 && identifierChar(glsl[p - 1])) continue;  // gl_in[v].gl_ClipDistance, a longer name
        size_t open = p + name.size(), close = matchingBracket(glsl, open);
        if (close == std::string::npos || close + 1 >= glsl.size() || glsl[close + 1] != '[') continue;
        out.append(glsl, at, p - at);
        out += "gl_in" + glsl.substr(open, close + 1 - open) + "." + name;
        at = close + 1;
    }
    out.append(glsl, at, std::string::npos);
    return out;
}

// `float p[n][k] = gl_ClipDistance;` (the whole input copied, as glslang's entry wrapper does for
// a float[k] per vertex) built element by element from gl_in.
std::string wholeCopies(const std::string& glsl, const std::string& name) {
    static const std::regex copy(R"(float (\w+)\[(\d+)\]\[(\d+)\] = (gl_ClipDistance|gl_CullDistance);)");
    std::string out;
    auto at = glsl.cbegin();
    for (std::sregex_iterator i(glsl.begin(), glsl.end(), copy), end; i != end; ++i) {
        const std::smatch& m = *i;
        if (m[4] != name) continue;
        const int n = std::stoi(m[2]), k = std::stoi(m[3]);
        std::string value = "float[" + m[2].str() + "][" + m[3].str() + "](";
        for (int v = 0; v < n; ++v) {
            value += std::string(v ? ", " : "") + "float[" + m[3].str() + "](";
            for (int e = 0; e < k; ++e) value += std::string(e ? ", " : "") + "gl_in[" + std::to_string(v) + "]." + name + "[" + std::to_string(e) + "]";
            value += ")";
        }
        out.append(at, m[0].first);
        out += "float " + m[1].str() + "[" + m[2].str() + "][" + m[3].str() + "] = " + value + ");";
        at = m[0].second;
    }
    out.append(at, glsl.cend());
    return out;
}

// gl_in's `float gl_ClipDistance[N];` sized `size` (the per-vertex element count).
std::string blockMemberSized(const std::string& glsl, const std::string& name, int size) {
    size_t block = glsl.find("in gl_PerVertex"), blockEnd = glsl.find("} gl_in[]", block);
    if (size <= 0 || block == std::string::npos || blockEnd == std::string::npos) return glsl;
    size_t member = glsl.find("float " + name + "[", block);
    if (member == std::string::npos || member > blockEnd) return glsl;
    size_t open = member + 6 + name.size(), close = glsl.find(']', open);
    return glsl.substr(0, open + 1) + std::to_string(size) + glsl.substr(close);
}

}  // namespace

std::string geometryClipInputsRespelled(const std::string& text, int clipSize, int cullSize) {
    std::string glsl = blockMemberSized(blockMemberSized(text, "gl_ClipDistance", clipSize), "gl_CullDistance", cullSize);
    return wholeCopies(wholeCopies(respell(respell(glsl, "gl_ClipDistance"), "gl_CullDistance"), "gl_ClipDistance"), "gl_CullDistance");
}

}  // namespace fxport::xlate
