// A pixel shader's GLSL as a compute shader (compute_pass_source.h): declarations are rewritten
// line by line (SPIRV-Cross writes one per line), identifiers are replaced as whole words, and
// the generated main rasterises the captured triangles per pixel the way GL does under
// glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE).
#include "compute_pass_source.h"

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
    text = replaceWord(text, "gl_FragCoord", "fxport_FragCoord");
    text = replaceWord(text, "discard", "{ fxport_discarded = true; return; }");
    result.text = text;
    return result;
}

std::string boundsShaderSource() {
    std::ostringstream s;
    s << "#version 450\n"
         "layout(local_size_x = 1) in;\n"
      << "layout(std430, binding = " << kCaptureBinding << ") readonly buffer fxport_Capture { float fxport_captured[]; };\n"
      << "layout(std430, binding = " << kDispatchBinding << ") writeonly buffer fxport_Dispatch { uint fxport_groups[3]; int fxport_origin[2]; };\n"
         "uniform ivec4 fxport_rect;\n"
         "uniform vec4 fxport_viewport;\n"
         "uniform int fxport_vertices;\n"
         "uniform int fxport_stride;\n"
         "void main() {\n"
         "    vec2 lo = vec2(fxport_rect.zw), hi = vec2(fxport_rect.xy);\n"
         "    bool bounded = true;\n"
         "    for (int v = 0; v < fxport_vertices; ++v) {\n"
         "        int b = v * fxport_stride;\n"
         "        vec4 c = vec4(fxport_captured[b], fxport_captured[b + 1], fxport_captured[b + 2], fxport_captured[b + 3]);\n"
         // Behind the eye or not finite: no rectangle from the projection; the whole one is safe.
         "        vec2 ndc = c.xy / c.w;\n"
         "        vec2 window = vec2(fxport_viewport.x + fxport_viewport.z * 0.5 * (ndc.x + 1.0),\n"
         "                           fxport_viewport.y + fxport_viewport.w * 0.5 * (1.0 - ndc.y));\n"
         "        if (!(c.w > 0.0) || any(isnan(window)) || any(isinf(window))) bounded = false;\n"
         "        lo = min(lo, window);\n"
         "        hi = max(hi, window);\n"
         "    }\n"
         "    ivec2 a = fxport_rect.xy, z = fxport_rect.zw;\n"
         // A pixel is drawn only if its centre is inside: one pixel of margin each way is plenty.
         "    if (bounded) {\n"
         "        a = ivec2(clamp(floor(lo) - 1.0, vec2(fxport_rect.xy), vec2(fxport_rect.zw)));\n"
         "        z = ivec2(clamp(ceil(hi) + 1.0, vec2(fxport_rect.xy), vec2(fxport_rect.zw)));\n"
         "    }\n"
         "    ivec2 size = max(z - a, ivec2(0));\n"
         "    fxport_groups[0] = uint((size.x + 7) / 8);\n"
         "    fxport_groups[1] = uint((size.y + 7) / 8);\n"
         "    fxport_groups[2] = 1u;\n"
         "    fxport_origin[0] = a.x;\n"
         "    fxport_origin[1] = a.y;\n"
         "}\n";
    return s.str();
}

int capturedFloatsPerVertex(const std::vector<GlslVarying>& captured) {
    int floats = 4;
    for (const GlslVarying& v : captured) floats += v.components;
    return floats;
}

std::string computeShaderSource(const PixelFunction& pixel, const std::vector<GlslVarying>& captured,
                                const std::vector<ComputeTarget>& targets, std::string& refusal) {
    const int stride = capturedFloatsPerVertex(captured);
    std::ostringstream s;
    s << "#version 450\n"
         "layout(local_size_x = 8, local_size_y = 8) in;\n"
         "vec4 fxport_FragCoord;\n"
         "bool fxport_discarded;\n"
      << pixel.text << "\n"
      << "layout(std430, binding = " << kCaptureBinding << ") readonly buffer fxport_Capture { float fxport_captured[]; };\n"
      << "layout(std430, binding = " << kDispatchBinding << ") readonly buffer fxport_Dispatch { uint fxport_groups[3]; int fxport_origin[2]; };\n";
    for (std::size_t t = 0; t < targets.size(); ++t)
        if (targets[t].writeMask != 0)
            s << "layout(binding = " << t << ", " << targets[t].imageFormat << ") uniform image2D fxport_target" << t << ";\n";
    s << "uniform ivec4 fxport_rect;\n"
         "uniform vec4 fxport_viewport;\n"
         "uniform vec2 fxport_depthRange;\n"
         "uniform int fxport_triangles;\n"
         "uniform int fxport_cull;\n"
         "vec4 fxport_read(int vertex, int offset) {\n"
         "    int b = vertex * " << stride << " + offset;\n"
         "    return vec4(fxport_captured[b], fxport_captured[b + 1], fxport_captured[b + 2], fxport_captured[b + 3]);\n"
         "}\n"
         "float fxport_component(int vertex, int offset) { return fxport_captured[vertex * " << stride << " + offset]; }\n"
         "void main() {\n"
         "    ivec2 pixel = ivec2(fxport_origin[0], fxport_origin[1]) + ivec2(gl_GlobalInvocationID.xy);\n"
         "    if (pixel.x >= fxport_rect.z || pixel.y >= fxport_rect.w) return;\n"
         // The rasteriser's grid: window coordinates in 1/256 pixel, exact in double.
         "    dvec2 centre = dvec2(pixel) * 256.0LF + 128.0LF;\n"
         "    bool written = false;\n";
    const char* swizzle[] = {"", ".x", ".xy", ".xyz", ""};
    for (std::size_t t = 0; t < targets.size(); ++t) {
        if (targets[t].writeMask == 0) continue;
        bool load = targets[t].writeMask != 15 || targets[t].color != BlendOp::Write || targets[t].alpha != BlendOp::Write;
        s << "    vec4 fxport_dst" << t << (load ? " = imageLoad(fxport_target" + std::to_string(t) + ", pixel)" : " = vec4(0.0)")
          << ";\n";
    }
    // Per-vertex values are arrays indexed by k, never vector components: NVIDIA's 580 driver
    // fails to link a write of a dvec3 component at a dynamic index (C9999, "can't find
    // __setVectorIndex function in stdlib"; H100 run of 2026-11-25).
    s << "    for (int t = 0; t < fxport_triangles; ++t) {\n"
         "        vec4 c[3]; vec3 ndc[3]; dvec2 s[3]; float zw[3];\n"
         "        bool behind = false, zInside = true;\n"
         "        for (int k = 0; k < 3; ++k) {\n"
         "            c[k] = fxport_read(t * 3 + k, 0);\n"
         "            behind = behind || !(c[k].w > 0.0);\n"
         "            zInside = zInside && c[k].z >= 0.0 && c[k].z <= c[k].w;\n"
         "            ndc[k] = c[k].xyz / c[k].w;\n"
         // GL's viewport transform with GL_UPPER_LEFT: window y grows as NDC y falls.
         "            vec2 window = vec2(fxport_viewport.x + fxport_viewport.z * 0.5 * (ndc[k].x + 1.0),\n"
         "                               fxport_viewport.y + fxport_viewport.w * 0.5 * (1.0 - ndc[k].y));\n"
         "            zw[k] = fxport_depthRange.x + (fxport_depthRange.y - fxport_depthRange.x) * ndc[k].z;\n"
         "            s[k] = round(dvec2(window) * 256.0LF);\n"
         "        }\n"
         "        if (behind) continue;\n"
         "        double area = (s[1].x - s[0].x) * (s[2].y - s[0].y) - (s[1].y - s[0].y) * (s[2].x - s[0].x);\n"
         // area > 0: clockwise as seen (y down), XNA's front face.
         "        if (area == 0.0LF || (fxport_cull == 1 && area < 0.0LF) || (fxport_cull == 2 && area > 0.0LF)) continue;\n"
         "        double orient = area > 0.0LF ? 1.0LF : -1.0LF;\n"
         "        double e[3]; bool inside = true;\n"
         "        for (int k = 0; k < 3; ++k) {\n"
         "            dvec2 a = s[(k + 1) % 3], b = s[(k + 2) % 3];\n"
         "            e[k] = ((b.x - a.x) * (centre.y - a.y) - (b.y - a.y) * (centre.x - a.x)) * orient;\n"
         "            dvec2 d = (b - a) * orient;\n"
         // D3D's top-left rule: a pixel centre on an edge belongs to the triangle whose top or left edge it is.
         "            bool topLeft = (d.y == 0.0LF && d.x > 0.0LF) || d.y < 0.0LF;\n"
         "            inside = inside && (e[k] > 0.0LF || (e[k] == 0.0LF && topLeft));\n"
         "        }\n"
         "        if (!inside) continue;\n"
         "        vec3 l = vec3(dvec3(e[0], e[1], e[2]) * orient / area);\n"
         "        float ndcZ = dot(l, vec3(ndc[0].z, ndc[1].z, ndc[2].z));\n"
         "        if (!zInside && (ndcZ < 0.0 || ndcZ > 1.0)) continue;\n"
         "        vec3 pw = l / vec3(c[0].w, c[1].w, c[2].w);\n"
         "        float invW = pw.x + pw.y + pw.z;\n"
         "        vec3 p = pw / invW;\n"
         "        fxport_FragCoord = vec4(vec2(pixel) + 0.5, dot(l, vec3(zw[0], zw[1], zw[2])), invW);\n";
    for (const GlslVarying& in : pixel.inputs) {
        int offset = 4;
        const GlslVarying* source = nullptr;
        for (const GlslVarying& v : captured) {
            if (v.location == in.location) {
                source = &v;
                break;
            }
            offset += v.components;
        }
        if (!source) {
            refusal = "pixel input '" + in.name + "' (location " + std::to_string(in.location) + ") has no vertex output";
            return {};
        }
        if (source->components < in.components || (source->scalar == 'f') != (in.scalar == 'f')) {
            refusal = "pixel input '" + in.name + "' is " + in.type + ", the vertex output is " + source->type;
            return {};
        }
        std::ostringstream value;
        if (in.scalar != 'f') {
            // Integers are flat; the provoking vertex is GL's default, the last.
            value << in.type << "((" << (in.scalar == 'i' ? "floatBitsToInt" : "floatBitsToUint")
                  << "(fxport_read(t * 3 + 2, " << offset << ")))" << swizzle[in.components] << ")";
        } else {
            auto at = [&](int k) { return "fxport_read(t * 3 + " + std::to_string(k) + ", " + std::to_string(offset) + ")"; };
            std::string weights = in.interpolation == Interpolation::NoPerspective ? "l" : "p";
            if (in.interpolation == Interpolation::Flat)
                value << in.type << "(" << at(2) << swizzle[in.components] << ")";
            else
                value << in.type << "((" << weights << ".x * " << at(0) << " + " << weights << ".y * " << at(1) << " + "
                      << weights << ".z * " << at(2) << ")" << swizzle[in.components] << ")";
        }
        // fxport_read reads 4 floats; the buffer holds at least a whole vertex past any offset
        // but the last vertex's tail, which the capture buffer pads (compute_pass.cpp).
        s << "        " << in.name << " = " << value.str() << ";\n";
    }
    s << "        fxport_discarded = false;\n"
         "        fxport_pixelMain();\n"
         "        if (fxport_discarded) continue;\n";
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
        const std::string dst = "fxport_dst" + std::to_string(t);
        std::string src = out->name;
        bool minMax = target.color == BlendOp::Min || target.color == BlendOp::Max || target.alpha == BlendOp::Min ||
                      target.alpha == BlendOp::Max;
        // GL clamps the source to the target's range before blending a fixed-point target.
        if (target.normalized && minMax) src = "clamp(" + src + ", 0.0, 1.0)";
        s << "        {\n            vec4 src = " << src << ";\n"
          << "            vec4 blended = vec4(" << op(target.color, "src.rgb", dst + ".rgb") << ", "
          << op(target.alpha, "src.a", dst + ".a") << ");\n";
        if (target.writeMask == 15) {
            s << "            " << dst << " = blended;\n";
        } else {
            unsigned m = target.writeMask;
            s << "            " << dst << " = mix(" << dst << ", blended, bvec4(" << ((m & 1) ? "true" : "false") << ", "
              << ((m & 2) ? "true" : "false") << ", " << ((m & 4) ? "true" : "false") << ", " << ((m & 8) ? "true" : "false")
              << "));\n";
        }
        s << "        }\n";
    }
    s << "        written = true;\n"
         "    }\n"
         "    if (!written) return;\n";
    for (std::size_t t = 0; t < targets.size(); ++t)
        if (targets[t].writeMask != 0) s << "    imageStore(fxport_target" << t << ", pixel, fxport_dst" << t << ");\n";
    s << "}\n";
    return s.str();
}

}  // namespace fxport::detail
