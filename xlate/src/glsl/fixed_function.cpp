// GLSL variants for the D3D9 fixed-function stages (see fixed_function.h). They rely on the shape
// of SPIRV-Cross's output: outputs and inputs declared `layout(location = N) out|in vec4 NAME;`, a
// `void main()`, the separable `out gl_PerVertex { ... }` block in vertex shaders.
#include "fxport/xlate/fixed_function.h"

#include <regex>

namespace fxport::xlate {

namespace {

const std::regex& entryPoint() {
    static const std::regex r(R"(\bvoid main\(\))");
    return r;
}

std::string renameMain(const std::string& glsl) {
    return std::regex_replace(glsl, entryPoint(), "void fxport_shaderMain()", std::regex_constants::format_first_only);
}

// The name of the vec4 varying declared at `location` with `direction` ("in"/"out"), or "".
std::string varyingAt(const std::string& glsl, int location, const char* direction) {
    const std::regex r("layout\\(location = " + std::to_string(location) + "\\) (?:flat |noperspective |centroid |sample )*" +
                       direction + " vec4 (\\w+);");
    std::smatch m;
    return std::regex_search(glsl, m, r) ? m[1].str() : std::string();
}

bool declaresLocation(const std::string& glsl, int location, const char* direction) {
    const std::regex r("layout\\(location = " + std::to_string(location) + "\\)[^;\\n]* " + direction + " ");
    return std::regex_search(glsl, r);
}

// Point sprites: TEXCOORDn inputs become globals the new main() fills from gl_PointCoord.
std::string spriteInputs(const std::string& glsl, std::string& prologue) {
    static const std::regex input(R"(layout\(location = (\d+)\) in vec4 (\w+);)");
    std::string out;
    auto last = glsl.cbegin();
    for (std::sregex_iterator it(glsl.begin(), glsl.end(), input), end; it != end; ++it) {
        const std::smatch& m = *it;
        if (std::stoi(m[1].str()) >= 16) continue;
        out.append(last, m[0].first);
        out += "vec4 " + m[2].str() + ";";
        last = m[0].second;
        // D3D9 puts (0, 0) at the sprite's top-left corner. GL's gl_PointCoord has t = 0 at the top
        // for the default POINT_SPRITE_COORD_ORIGIN (UPPER_LEFT) in window coordinates, whose rows
        // fxport's upper-left clip origin turns over (row 0 is the target's top): t is flipped.
        prologue += "    " + m[2].str() + " = vec4(gl_PointCoord.x, 1.0 - gl_PointCoord.y, 0.0, 1.0);\n";
    }
    out.append(last, glsl.cend());
    return out;
}

std::string flatColourInputs(const std::string& glsl) {
    static const std::regex colour(R"(layout\(location = (1[6-9])\) in )");
    return std::regex_replace(glsl, colour, "layout(location = $1) flat in ");
}

std::string alphaTestCode(const std::string& target) {
    return "    {\n        float a = " + target + ".a;\n        float r = fxport_AlphaRef;\n        int f = fxport_AlphaFunc;\n"
           "        bool keep = f == 8 || (f == 2 && a < r) || (f == 3 && a == r) || (f == 4 && a <= r) ||\n"
           "                    (f == 5 && a > r) || (f == 6 && a != r) || (f == 7 && a >= r);\n"
           "        if (!keep) discard;\n    }\n";
}

std::string fogCode(const std::string& target, const std::string& vertexFactor) {
    return "    {\n"
           "        float d = fxport_FogParams.w != 0.0 ? 1.0 / gl_FragCoord.w : gl_FragCoord.z;\n"
           "        float f = " + vertexFactor + ";\n"
           "        if (fxport_FogMode == 1) f = exp(-fxport_FogParams.z * d);\n"
           "        else if (fxport_FogMode == 2) f = exp(-(fxport_FogParams.z * d) * (fxport_FogParams.z * d));\n"
           "        else if (fxport_FogMode == 3) f = (fxport_FogParams.x - d) * fxport_FogParams.y;\n"
           "        " + target + ".rgb = mix(fxport_FogColor.rgb, " + target + ".rgb, clamp(f, 0.0, 1.0));\n"
           "    }\n";
}

}  // namespace

std::optional<std::string> pixelFixedFunctionVariant(const std::string& glsl, const PixelFixedFunction& wanted, std::string& why) {
    std::string target;
    if (wanted.alphaTest || wanted.fog) {
        target = varyingAt(glsl, 0, "out");
        if (target.empty()) {
            why = "the shader writes no float4 colour to render target 0";
            return std::nullopt;
        }
    }
    if (!std::regex_search(glsl, entryPoint())) {
        why = "the GLSL has no main()";
        return std::nullopt;
    }
    std::string out = glsl, prologue, declarations, epilogue;
    if (wanted.pointSprite) out = spriteInputs(out, prologue);
    if (wanted.flatColors) out = flatColourInputs(out);
    if (wanted.fog) {
        std::string factor = "0.0";  // no FOG or COLOR1 written: D3D reads 0 from an unwritten output
        if (wanted.fogInput.location >= 0) {
            std::string name = varyingAt(out, wanted.fogInput.location, "in");
            if (name.empty()) {
                if (declaresLocation(out, wanted.fogInput.location, "in")) {
                    why = "the shader reads a non-float4 input where the fog factor arrives";
                    return std::nullopt;
                }
                name = "fxport_FogInput";
                declarations += "layout(location = " + std::to_string(wanted.fogInput.location) + ") in vec4 " + name + ";\n";
            }
            factor = name + (wanted.fogInput.component == 3 ? ".w" : ".x");
        }
        declarations += "uniform vec4 fxport_FogColor;\nuniform int fxport_FogMode;\nuniform vec4 fxport_FogParams;\n";
        epilogue += fogCode(target, factor);
    }
    if (wanted.alphaTest) {
        declarations += "uniform int fxport_AlphaFunc;\nuniform float fxport_AlphaRef;\n";
        epilogue += alphaTestCode(target);
    }
    out = renameMain(out);
    out += "\n" + declarations + "\nvoid main()\n{\n" + prologue + "    fxport_shaderMain();\n" + epilogue + "}\n";
    return out;
}

std::optional<std::string> vertexFixedFunctionVariant(const std::string& glsl, const VertexFixedFunction& wanted, std::string& why) {
    static const std::regex perVertex(R"(out gl_PerVertex\s*\{)");
    std::smatch m;
    if (!std::regex_search(glsl, m, perVertex) || !std::regex_search(glsl, entryPoint())) {
        why = "the GLSL has no gl_PerVertex block or no main()";
        return std::nullopt;
    }
    if (wanted.clipPlanes > 0 && glsl.find("gl_ClipDistance") != std::string::npos) {
        why = "the vertex shader writes SV_ClipDistance itself";
        return std::nullopt;
    }
    std::string members, declarations, epilogue;
    if (wanted.clipPlanes > 0) {
        members += "\n    float gl_ClipDistance[" + std::to_string(wanted.clipPlanes) + "];";
        declarations += "uniform vec4 fxport_ClipPlanes[" + std::to_string(kMaxUserClipPlanes) + "];\n";
        // D3D9 clips the position the shader wrote: gl_Position (the D3D9 pixel centres are the
        // viewport's, not the shader's).
        epilogue += "    vec4 fxport_clipPosition = gl_Position;\n";
        for (int i = 0; i < wanted.clipPlanes; ++i)
            epilogue += "    gl_ClipDistance[" + std::to_string(i) + "] = dot(fxport_clipPosition, fxport_ClipPlanes[" + std::to_string(i) + "]);\n";
    }
    if (wanted.pointSizeLocation >= 0) {
        const std::string size = varyingAt(glsl, wanted.pointSizeLocation, "out");
        if (size.empty()) {
            why = "no float4 output at the PSIZE location";
            return std::nullopt;
        }
        members += "\n    float gl_PointSize;";
        declarations += "uniform vec4 fxport_PointSize;\n";
        epilogue += "    gl_PointSize = clamp(" + size + ".x, fxport_PointSize.y, fxport_PointSize.z);\n";
    }
    std::string out = glsl;
    out.insert(std::size_t(m.position(0) + m.length(0)), members);
    out = renameMain(out);
    out += "\n" + declarations + "\nvoid main()\n{\n    fxport_shaderMain();\n" + epilogue + "}\n";
    return out;
}

}  // namespace fxport::xlate
