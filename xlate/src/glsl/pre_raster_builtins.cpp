#include "glsl/pre_raster_builtins.h"

namespace fxport::xlate {

// D3D's SV_VertexID leaves out StartVertexLocation and BaseVertexLocation: HLSL's SM 6.8 proposal
// 0015 (microsoft/hlsl-specs, proposals/0015-extended-command-info.md): "SV_VertexID doesn't include
// the StartVertexLocation", which is why SV_StartVertexLocation was added; DXVK and vkd3d-shader
// subtract Vulkan's BaseVertex from VertexIndex for it. GL's gl_VertexID is first + i for
// glDrawArrays and index + basevertex for glDrawElementsBaseVertex, and GL's gl_BaseVertex is 0 for
// glDrawArrays, so the runtime hands the value in (one uniform for both kinds of draw).
std::string vertexIdExpression() { return std::string("(gl_VertexID - ") + kStartVertexUniform + ")"; }

std::string withStartVertexDeclared(const std::string& glsl) {
    std::size_t at = 0;
    while (at < glsl.size() && (glsl[at] == '#' || glsl[at] == '\n')) {
        const std::size_t end = glsl.find('\n', at);
        if (end == std::string::npos) return glsl;
        at = end + 1;
    }
    return glsl.substr(0, at) + "uniform int " + kStartVertexUniform + ";\n" + glsl.substr(at);
}

std::vector<std::string> layerViewportExtensionLines(ShaderStage stage, bool layer, bool viewport) {
    std::vector<std::string> lines;
    if (!layer && !viewport) return lines;
    const std::string what = layer && viewport ? "SV_RenderTargetArrayIndex and SV_ViewportArrayIndex"
                             : layer           ? "SV_RenderTargetArrayIndex"
                                               : "SV_ViewportArrayIndex";
    const std::string shader = stage == ShaderStage::Domain ? "domain" : "vertex";
    lines.push_back("#if defined(GL_ARB_shader_viewport_layer_array)");
    lines.push_back("#extension GL_ARB_shader_viewport_layer_array : require");
    lines.push_back("#elif defined(GL_NV_viewport_array2)");
    lines.push_back("#extension GL_NV_viewport_array2 : require");
    // The AMD pair are for vertex shaders only.
    if (stage == ShaderStage::Vertex) {
        std::string amd = "#elif";
        if (layer) amd += " defined(GL_AMD_vertex_shader_layer)";
        if (layer && viewport) amd += " &&";
        if (viewport) amd += " defined(GL_AMD_vertex_shader_viewport_index)";
        lines.push_back(amd);
        if (layer) lines.push_back("#extension GL_AMD_vertex_shader_layer : require");
        if (viewport) lines.push_back("#extension GL_AMD_vertex_shader_viewport_index : require");
    }
    lines.push_back("#else");
    lines.push_back("#error fxport: this " + shader + " shader writes " + what +
                    ": that needs GL_ARB_shader_viewport_layer_array (or GL_NV_viewport_array2" +
                    std::string(stage == ShaderStage::Vertex ? ", or the GL_AMD_vertex_shader_ pair" : "") + "), which the GL driver lacks");
    lines.push_back("#endif");
    return lines;
}

std::string perVertexForLayerOutputs(const std::string& glsl) {
    const std::size_t begin = glsl.find("out gl_PerVertex");
    if (begin == std::string::npos || (begin > 0 && glsl[begin - 1] != '\n')) return glsl;
    const std::size_t close = glsl.find("};", begin);
    if (close == std::string::npos) return glsl;
    const std::size_t end = close + 2;
    return glsl.substr(0, begin) + "#if defined(GL_NV_viewport_array2)\n" + glsl.substr(begin, end - begin) + "\n#endif" +
           glsl.substr(end);
}

}  // namespace fxport::xlate
