// A pixel shader's GLSL as a compute shader (compute_pass_source.h): declarations are rewritten
// line by line (SPIRV-Cross writes one per line), identifiers are replaced as whole words, and the
// generated main reads the inputs the rasteriser interpolated from the replay store. The fill and
// compare steps that keep the store right are generated here too.
#include "gl/passes/compute_pass_source.h"

#include <regex>
#include <sstream>

namespace fxport::detail {

namespace {

bool isWordChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Positions of `word` as a whole identifier in `text`.
std::vector<std::size_t> findWord(const std::string& text, const std::string& word) {
    std::vector<std::size_t> at;
    for (std::size_t p = text.find(word); p != std::string::npos; p = text.find(word, p + 1)) {
        bool before = p > 0 && isWordChar(text[p - 1]);
        bool after = p + word.size() < text.size() && isWordChar(text[p + word.size()]);
        if (!before && !after) at.push_back(p);
    }
    return at;
}

std::string replaceWord(const std::string& text, const std::string& word, const std::string& with) {
    std::string out;
    std::size_t from = 0;
    for (std::size_t p : findWord(text, word)) {
        out.append(text, from, p - from);
        out += with;
        from = p + word.size();
    }
    out.append(text, from, std::string::npos);
    return out;
}

// vecN / ivecN / uvecN / float / int / uint -> components and scalar kind; false for others.
bool scalarShape(const std::string& type, int& components, char& scalar) {
    static const std::regex vector(R"(^([iu]?)vec([234])$)");
    std::smatch m;
    if (type == "float" || type == "int" || type == "uint") {
        components = 1;
        scalar = type[0] == 'f' ? 'f' : type[0];
        return true;
    }
    if (std::regex_match(type, m, vector)) {
        components = m[2].str()[0] - '0';
        scalar = m[1].str().empty() ? 'f' : m[1].str()[0];
        return true;
    }
    return false;
}

// `layout(location = N) [flat|noperspective|smooth|centroid ]* in|out TYPE NAME;`
const std::regex& locatedDeclaration() {
    static const std::regex r(
        R"(^\s*layout\s*\(\s*location\s*=\s*(\d+)\s*\)\s*((?:(?:flat|noperspective|smooth|centroid)\s+)*)(in|out)\s+(\w+)\s+(\w+)\s*;\s*$)");
    return r;
}

// A top-level line that declares an interface variable or block (begins with a storage or
// interpolation qualifier, possibly after a layout).
bool declaresInterface(const std::string& line) {
    static const std::regex r(R"(^\s*(layout\s*\([^)]*\)\s*)?((flat|noperspective|smooth|centroid|sample|patch)\s+)*(in|out)\b)");
    return std::regex_search(line, r);
}

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// Brace depth before each line (what is at depth 0 is a global declaration).
std::vector<int> depthBefore(const std::vector<std::string>& lines) {
    std::vector<int> depth;
    int d = 0;
    for (const std::string& line : lines) {
        depth.push_back(d);
        for (char c : line) d += c == '{' ? 1 : c == '}' ? -1 : 0;
    }
    return depth;
}

const char* const kRefusedWords[] = {
    "dFdx", "dFdy", "fwidth", "dFdxFine", "dFdyFine", "dFdxCoarse", "dFdyCoarse", "fwidthFine", "fwidthCoarse",
    "interpolateAtCentroid", "interpolateAtSample", "interpolateAtOffset", "gl_FrontFacing", "gl_SampleID",
    "gl_SamplePosition", "gl_FragDepth", "gl_SampleMask", "gl_SampleMaskIn", "gl_HelperInvocation",
    "gl_PrimitiveID", "gl_Layer", "gl_ViewportIndex", "gl_ClipDistance", "gl_CullDistance", "gl_PointCoord",
    "gl_FragColor", "gl_FragData", "textureQueryLod", "textureQueryLOD", "early_fragment_tests", "buffer",
    "imageStore", "imageLoad", "fxport_FragCoord", "fxport_discarded", "fxport_pixelMain"};

}  // namespace

VertexOutputs parseVertexOutputs(const std::string& glsl) {
    VertexOutputs result;
    std::vector<std::string> lines = splitLines(glsl);
    std::vector<int> depth = depthBefore(lines);
    for (std::size_t i = 0; i < lines.size(); ++i) {
        if (depth[i] != 0 || !declaresInterface(lines[i])) continue;
        std::smatch m;
        if (std::regex_match(lines[i], m, locatedDeclaration())) {
            if (m[3] == "in") continue;
            GlslVarying v;
            v.location = std::stoi(m[1]);
            v.type = m[4];
            v.name = m[5];
            if (!scalarShape(v.type, v.components, v.scalar)) {
                result.refusal = "vertex output '" + v.name + "' of type " + v.type;
                return result;
            }
            result.varyings.push_back(v);
        } else if (lines[i].find("out gl_PerVertex") == std::string::npos && lines[i].find(" out") != std::string::npos) {
            result.refusal = "vertex output declaration '" + lines[i] + "'";
            return result;
        }
    }
    return result;
}

PixelFunction pixelFunctionFromShader(const std::string& glsl) {
    PixelFunction result;
    for (const char* word : kRefusedWords)
        if (!findWord(glsl, word).empty()) {
            result.refusal = std::string("uses ") + word;
            return result;
        }
    if (glsl.find("#extension") != std::string::npos) {
        result.refusal = "enables a GLSL extension";
        return result;
    }
    std::vector<std::string> lines = splitLines(glsl);
    std::vector<int> depth = depthBefore(lines);
    std::string text;
    int mainLine = -1;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const std::string& line = lines[i];
        if (depth[i] == 0 && line.rfind("#version", 0) == 0) continue;
        if (depth[i] == 0 && declaresInterface(line)) {
            std::smatch m;
            if (!std::regex_match(line, m, locatedDeclaration())) {
                result.refusal = "declares '" + line + "'";
                return result;
            }
            GlslVarying v;
            v.location = std::stoi(m[1]);
            v.type = m[4];
            v.name = m[5];
            const std::string qualifiers = m[2];
            v.qualifiers = qualifiers;
            if (qualifiers.find("flat") != std::string::npos) v.interpolation = Interpolation::Flat;
            else if (qualifiers.find("noperspective") != std::string::npos) v.interpolation = Interpolation::NoPerspective;
            if (!scalarShape(v.type, v.components, v.scalar)) {
                result.refusal = "declares '" + v.name + "' of type " + v.type;
                return result;
            }
            if (m[3] == "out") {
                if (v.type != "vec4") {  // GL leaves the missing channels undefined
                    result.refusal = "writes " + v.type + " to render target " + std::to_string(v.location);
                    return result;
                }
                result.outputs.push_back(v);
            } else {
                result.inputs.push_back(v);
            }
            text += v.type + " " + v.name + ";\n";
            continue;
        }
        if (depth[i] == 0 && std::regex_search(line, std::regex(R"(^\s*void\s+main\s*\(\s*(void)?\s*\))"))) {
            mainLine = int(i);
            text += "void fxport_pixelMain()\n";
            continue;
        }
        text += line + "\n";
    }
    if (mainLine < 0) {
        result.refusal = "has no main()";
        return result;
    }
    // `discard` ends the invocation; as a function it can only return, so it must be in main.
    std::size_t mainStart = 0;
    for (int i = 0; i < mainLine; ++i) mainStart += lines[std::size_t(i)].size() + 1;
    int d = 0;
    std::size_t mainEnd = std::string::npos;
    for (std::size_t p = glsl.find('{', mainStart); p < glsl.size(); ++p) {
        d += glsl[p] == '{' ? 1 : glsl[p] == '}' ? -1 : 0;
        if (d == 0) {
            mainEnd = p;
            break;
        }
    }
    for (std::size_t p : findWord(glsl, "discard"))
        if (p < mainStart || p > mainEnd) {
            result.refusal = "discards outside main()";
            return result;
        }
    result.readsFragCoord = !findWord(text, "gl_FragCoord").empty();
    // Which components each input is read at: `name.xy` marks x and y; any other use (whole,
    // indexed, passed on) marks all of them. SPIRV-Cross declares a ps_2_0 TEXCOORD0 as vec4 and
    // reads .xy: half the replay store.
    for (GlslVarying& in : result.inputs) {
        in.readMask = 0;
        const std::string declared = in.type + " ";
        for (std::size_t p : findWord(text, in.name)) {
            const bool declaration = p >= declared.size() && text.compare(p - declared.size(), declared.size(), declared) == 0 &&
                                     (p == declared.size() || text[p - declared.size() - 1] == '\n');
            if (declaration) continue;  // its global "vec4 name;" (above)
            std::size_t q = p + in.name.size();
            unsigned mask = 0;
            if (q < text.size() && text[q] == '.') {
                static const std::string kSwizzle = "xyzwrgba";
                for (++q; q < text.size() && isWordChar(text[q]); ++q) {
                    const std::size_t c = kSwizzle.find(text[q]);
                    if (c == std::string::npos) {
                        mask = 15;
                        break;
                    }
                    mask |= 1u << (c % 4);
                }
            } else {
                mask = 15;
            }
            in.readMask |= mask;
        }
        in.readMask &= (1u << in.components) - 1u;
    }
    text = replaceWord(text, "gl_FragCoord", "fxport_FragCoord");
    text = replaceWord(text, "discard", "{ fxport_discarded = true; return; }");
    result.text = text;
    return result;
}

namespace {

// The commands block as every generated program declares it (compute_pass_source.h's word offsets).
std::string commandsBlock(const char* access) {
    std::ostringstream s;
    s << "layout(std430, binding = " << kCommandsBinding << ") " << access
      << " buffer fxport_Commands {\n"
         "    uint fxport_groups[3]; int fxport_origin[2]; uint fxport_currentStamp; uint fxport_pad0[2];\n"
         "    uint fxport_fill[5]; uint fxport_pad1[3];\n"
         "    uint fxport_fallBack[5]; uint fxport_pad2[3];\n"
         "};\n";
    return s.str();
}

const char* const kComponent[] = {".x", ".y", ".z", ".w"};

}  // namespace

std::string compareShaderSource() {
    std::ostringstream s;
    s << "#version 450\n"
         "layout(local_size_x = 1) in;\n"
      << "layout(std430, binding = " << kCaptureBinding << ") readonly buffer fxport_Capture { float fxport_captured[]; };\n"
      << commandsBlock("")
      << "layout(std430, binding = " << kCountersBinding << ") buffer fxport_Counters { uint fxport_counters[4]; };\n"
      << "layout(std430, binding = " << kEntryBinding
      << ") buffer fxport_Entry { uint fxport_entryStamp; uint fxport_pad3[3]; uint fxport_stored[]; };\n"
         "uniform ivec4 fxport_rect;\n"
         "uniform vec4 fxport_viewport;\n"
         "uniform int fxport_vertices;\n"
         "uniform int fxport_stride;\n"
         "uniform int fxport_unitW;\n"
         "uniform uint fxport_stamp;\n"
         "uniform ivec4 fxport_draw;\n"
         "vec4 fxport_clip(int v) {\n"
         "    int b = v * fxport_stride;\n"
         "    return vec4(fxport_captured[b], fxport_captured[b + 1], fxport_captured[b + 2], fxport_captured[b + 3]);\n"
         "}\n"
         "vec2 fxport_window(vec4 c) {\n"
         "    vec2 ndc = c.xy / c.w;\n"
         // GL's viewport transform under GL_UPPER_LEFT: window y grows as NDC y falls.
         "    return vec2(fxport_viewport.x + fxport_viewport.z * 0.5 * (ndc.x + 1.0),\n"
         "                fxport_viewport.y + fxport_viewport.w * 0.5 * (1.0 - ndc.y));\n"
         "}\n"
         "void main() {\n"
         "    vec2 lo = vec2(fxport_rect.zw), hi = vec2(fxport_rect.xy);\n"
         "    bool bounded = true, unitW = true, inside = true;\n"
         "    for (int v = 0; v < fxport_vertices; ++v) {\n"
         "        vec4 c = fxport_clip(v);\n"
         "        vec2 window = fxport_window(c);\n"
         // Behind the eye or not finite: no rectangle from the projection; the whole one is safe.
         "        if (!(c.w > 0.0) || any(isnan(window)) || any(isinf(window))) bounded = false;\n"
         "        if (c.w != 1.0) unitW = false;\n"
         // Inside the clip volume (with room in x and y for a guard band): the rasteriser does not
         // clip, so two triangles' shared edge is the same edge in both.
         "        if (!(c.w > 0.0 && c.z >= 0.0 && c.z <= c.w && abs(c.x) <= 16.0 * c.w && abs(c.y) <= 16.0 * c.w)) inside = false;\n"
         "        lo = min(lo, window);\n"
         "        hi = max(hi, window);\n"
         "    }\n"
         // Two triangles must not cover a pixel twice: a quad, its two triangles on opposite sides
         // of their shared edge (bit-identical clip positions), each third vertex over a pixel away.
         "    bool oneLayer = fxport_vertices == 3;\n"
         "    if (fxport_vertices == 6 && inside) {\n"
         "        int matches = 0; int a[2]; int b[2];\n"
         "        for (int i = 0; i < 3; ++i)\n"
         "            for (int j = 3; j < 6; ++j)\n"
         "                if (all(equal(floatBitsToUint(fxport_clip(i)), floatBitsToUint(fxport_clip(j))))) {\n"
         "                    if (matches < 2) { a[matches] = i; b[matches] = j; }\n"
         "                    ++matches;\n"
         "                }\n"
         "        if (matches == 2 && a[0] != a[1] && b[0] != b[1]) {\n"
         "            dvec2 p = dvec2(fxport_window(fxport_clip(a[0]))), q = dvec2(fxport_window(fxport_clip(a[1])));\n"
         "            dvec2 u = dvec2(fxport_window(fxport_clip(3 - a[0] - a[1])));\n"
         "            dvec2 w = dvec2(fxport_window(fxport_clip(12 - b[0] - b[1])));\n"
         "            dvec2 edge = q - p;\n"
         "            double eu = edge.x * (u.y - p.y) - edge.y * (u.x - p.x);\n"
         "            double ew = edge.x * (w.y - p.y) - edge.y * (w.x - p.x);\n"
         "            double reach = length(vec2(edge));\n"
         "            oneLayer = reach > 0.0LF && eu * ew < 0.0LF && abs(eu) > reach && abs(ew) > reach;\n"
         "        }\n"
         "    }\n"
         "    bool replays = (unitW || fxport_unitW == 0) && oneLayer;\n"
         "    bool same = fxport_entryStamp != 0u;\n"
         "    int floats = fxport_vertices * fxport_stride;\n"
         "    for (int i = 0; i < floats && same; ++i) same = floatBitsToUint(fxport_captured[i]) == fxport_stored[i];\n"
         "    bool refill = replays && !same;\n"
         "    if (refill) {\n"
         "        for (int i = 0; i < floats; ++i) fxport_stored[i] = floatBitsToUint(fxport_captured[i]);\n"
         "        fxport_entryStamp = fxport_stamp;\n"
         "    }\n"
         "    if (refill) fxport_counters[0] += 1u;\n"
         "    else if (replays) fxport_counters[1] += 1u;\n"
         "    else if (!oneLayer) fxport_counters[3] += 1u;\n"
         "    else fxport_counters[2] += 1u;\n"
         "    ivec2 from = fxport_rect.xy, to = fxport_rect.zw;\n"
         // A pixel is drawn only if its centre is inside: one pixel of margin each way is plenty.
         "    if (bounded) {\n"
         "        from = ivec2(clamp(floor(lo) - 1.0, vec2(fxport_rect.xy), vec2(fxport_rect.zw)));\n"
         "        to = ivec2(clamp(ceil(hi) + 1.0, vec2(fxport_rect.xy), vec2(fxport_rect.zw)));\n"
         "    }\n"
         "    ivec2 size = replays ? max(to - from, ivec2(0)) : ivec2(0);\n"
         "    fxport_groups[0] = uint((size.x + 7) / 8);\n"
         "    fxport_groups[1] = uint((size.y + 7) / 8);\n"
         "    fxport_groups[2] = 1u;\n"
         "    fxport_origin[0] = from.x;\n"
         "    fxport_origin[1] = from.y;\n"
         "    fxport_currentStamp = fxport_entryStamp;\n"
         // DrawArraysIndirectCommand {count, instances, first, base instance} or
         // DrawElementsIndirectCommand {count, instances, first index, base vertex, base instance}.
         "    uint command[5] = uint[5](uint(fxport_draw.x), 0u, uint(fxport_draw.y), uint(fxport_draw.w != 0 ? fxport_draw.z : 0), 0u);\n"
         "    for (int i = 0; i < 5; ++i) { fxport_fill[i] = command[i]; fxport_fallBack[i] = command[i]; }\n"
         "    fxport_fill[1] = refill ? 1u : 0u;\n"
         "    fxport_fallBack[1] = replays ? 0u : 1u;\n"
         "}\n";
    return s.str();
}

int capturedFloatsPerVertex(const std::vector<GlslVarying>& captured) {
    int floats = 4;
    for (const GlslVarying& v : captured) floats += v.components;
    return floats;
}

int replayLayers(const PixelFunction& pixel) {
    int layers = 1;
    for (const GlslVarying& in : pixel.inputs)
        for (int c = 0; c < in.components; ++c) layers += (in.readMask >> c) & 1u;
    return layers + (pixel.readsFragCoord ? 2 : 0);
}

std::string inputSignature(const PixelFunction& pixel) {
    std::string signature;
    for (const GlslVarying& in : pixel.inputs)
        signature += std::to_string(in.location) + in.qualifiers + in.type + ":" + std::to_string(in.readMask) + ",";
    return signature + (pixel.readsFragCoord ? "fragcoord" : "");
}

bool hasPerspectiveInput(const PixelFunction& pixel) {
    for (const GlslVarying& in : pixel.inputs)
        if (in.scalar == 'f' && in.interpolation == Interpolation::Smooth && in.readMask != 0) return true;
    return false;
}

std::string inputsRefusal(const PixelFunction& pixel, const std::vector<GlslVarying>& captured) {
    for (const GlslVarying& in : pixel.inputs) {
        const GlslVarying* source = nullptr;
        for (const GlslVarying& v : captured)
            if (v.location == in.location) source = &v;
        if (!source) return "pixel input '" + in.name + "' (location " + std::to_string(in.location) + ") has no vertex output";
        if (source->components < in.components || (source->scalar == 'f') != (in.scalar == 'f'))
            return "pixel input '" + in.name + "' is " + in.type + ", the vertex output is " + source->type;
    }
    return {};
}

std::string fillShaderSource(const PixelFunction& pixel) {
    std::ostringstream s;
    s << "#version 450\n";
    for (const GlslVarying& in : pixel.inputs)
        s << "layout(location = " << in.location << ") " << in.qualifiers << "in " << in.type << " " << in.name << ";\n";
    s << "layout(binding = " << kStoreUnit << ", r32ui) writeonly uniform uimage2DArray fxport_store;\n"
         "uniform uint fxport_stamp;\n"
         "void main() {\n"
         "    ivec2 pixel = ivec2(gl_FragCoord.xy);\n";
    int layer = 1;
    auto store = [&](const std::string& value) {
        s << "    imageStore(fxport_store, ivec3(pixel, " << layer++ << "), uvec4(" << value << "));\n";
    };
    for (const GlslVarying& in : pixel.inputs)
        for (int c = 0; c < in.components; ++c) {
            if (!((in.readMask >> c) & 1u)) continue;
            const std::string component = in.name + (in.components > 1 ? kComponent[c] : "");
            store(in.scalar == 'f' ? "floatBitsToUint(" + component + ")" : "uint(" + component + ")");
        }
    if (pixel.readsFragCoord) {
        store("floatBitsToUint(gl_FragCoord.z)");
        store("floatBitsToUint(gl_FragCoord.w)");
    }
    // The stamp last: the compute pass reads a pixel whose stamp is the current fill's.
    s << "    imageStore(fxport_store, ivec3(pixel, 0), uvec4(fxport_stamp));\n"
         "}\n";
    return s.str();
}

std::string computeShaderSource(const PixelFunction& pixel, const std::vector<ComputeTarget>& targets, std::string& refusal) {
    std::ostringstream s;
    s << "#version 450\n"
         "layout(local_size_x = 8, local_size_y = 8) in;\n"
         "vec4 fxport_FragCoord;\n"
         "bool fxport_discarded;\n"
      << pixel.text << "\n"
      << commandsBlock("readonly")
      << "layout(binding = " << kStoreUnit << ", r32ui) readonly uniform uimage2DArray fxport_store;\n";
    for (std::size_t t = 0; t < targets.size(); ++t)
        if (targets[t].writeMask != 0)
            s << "layout(binding = " << t << ", " << targets[t].imageFormat << ") uniform image2D fxport_target" << t << ";\n";
    s << "uniform ivec4 fxport_rect;\n"
         "uint fxport_stored(ivec2 pixel, int layer) { return imageLoad(fxport_store, ivec3(pixel, layer)).x; }\n"
         "void main() {\n"
         "    ivec2 pixel = ivec2(fxport_origin[0], fxport_origin[1]) + ivec2(gl_GlobalInvocationID.xy);\n"
         "    if (pixel.x >= fxport_rect.z || pixel.y >= fxport_rect.w) return;\n"
         // Coverage is the rasteriser's: the fill wrote this fill's stamp where it covered.
         "    if (fxport_stored(pixel, 0) != fxport_currentStamp) return;\n";
    int layer = 1;
    for (const GlslVarying& in : pixel.inputs) {
        // One layer per component, read as arrays of scalars (never a vector component at a
        // dynamic index: NVIDIA's 580 driver fails to link some of those).
        std::string parts;
        // A component the shader never reads is not stored: 0.
        for (int c = 0; c < in.components; ++c) {
            std::string value = in.scalar == 'f' ? "0.0" : in.scalar == 'i' ? "0" : "0u";
            if ((in.readMask >> c) & 1u) {
                const std::string bits = "fxport_stored(pixel, " + std::to_string(layer++) + ")";
                value = in.scalar == 'f' ? "uintBitsToFloat(" + bits + ")" : in.scalar == 'i' ? "int(" + bits + ")" : bits;
            }
            parts += (c ? ", " : "") + value;
        }
        s << "    " << in.name << " = " << in.type << "(" << parts << ");\n";
    }
    if (pixel.readsFragCoord) {
        s << "    fxport_FragCoord = vec4(vec2(pixel) + 0.5, uintBitsToFloat(fxport_stored(pixel, " << layer
          << ")), uintBitsToFloat(fxport_stored(pixel, " << layer + 1 << ")));\n";
        layer += 2;
    }
    s << "    fxport_discarded = false;\n"
         "    fxport_pixelMain();\n"
         "    if (fxport_discarded) return;\n";
    auto op = [](BlendOp o, const std::string& src, const std::string& dst) {
        switch (o) {
        case BlendOp::Write: return src;
        case BlendOp::Add: return src + " + " + dst;
        case BlendOp::Min: return "min(" + src + ", " + dst + ")";
        case BlendOp::Max: return "max(" + src + ", " + dst + ")";
        }
        return src;
    };
    for (std::size_t t = 0; t < targets.size(); ++t) {
        const ComputeTarget& target = targets[t];
        if (target.writeMask == 0) continue;
        const GlslVarying* out = nullptr;
        for (const GlslVarying& o : pixel.outputs)
            if (o.location == int(t)) out = &o;
        if (!out) {
            refusal = "render target " + std::to_string(t) + " has no pixel shader output";
            return {};
        }
        const std::string image = "fxport_target" + std::to_string(t);
        std::string src = out->name;
        const bool load = target.writeMask != 15 || target.color != BlendOp::Write || target.alpha != BlendOp::Write;
        const bool minMax = target.color == BlendOp::Min || target.color == BlendOp::Max || target.alpha == BlendOp::Min ||
                            target.alpha == BlendOp::Max;
        // GL clamps the source to the target's range before blending a fixed-point target.
        if (target.normalized && minMax) src = "clamp(" + src + ", 0.0, 1.0)";
        s << "    {\n        vec4 src = " << src << ";\n";
        if (!load) {
            s << "        imageStore(" << image << ", pixel, src);\n    }\n";
            continue;
        }
        s << "        vec4 dst = imageLoad(" << image << ", pixel);\n"
          << "        vec4 blended = vec4(" << op(target.color, "src.rgb", "dst.rgb") << ", " << op(target.alpha, "src.a", "dst.a")
          << ");\n";
        const unsigned m = target.writeMask;
        auto on = [&](unsigned bit) { return (m & bit) ? "true" : "false"; };
        if (m != 15) s << "        blended = mix(dst, blended, bvec4(" << on(1) << ", " << on(2) << ", " << on(4) << ", " << on(8) << "));\n";
        s << "        imageStore(" << image << ", pixel, blended);\n    }\n";
    }
    s << "}\n";
    return s.str();
}

}  // namespace fxport::detail
