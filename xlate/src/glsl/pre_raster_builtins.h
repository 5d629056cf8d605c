// INTERNAL: D3D system values of the vertex stages that GL has no plain core built-in for.
//  - SV_VertexID: gl_VertexID less the draw's start vertex (kStartVertexUniform, compiled_effect.h).
//  - SV_RenderTargetArrayIndex / SV_ViewportArrayIndex written by a vertex or domain shader (D3D11.3
//    VPRT, single-pass stereo): gl_Layer / gl_ViewportIndex there need an extension
//    (GL_ARB_shader_viewport_layer_array, or NV_viewport_array2 / AMD_vertex_shader_layer and
//    _viewport_index); a driver with none stops at an #error naming the semantic and extension,
//    rather than the primitives all going to layer and viewport 0.
#pragma once

#include <string>
#include <vector>

#include "fxport/xlate/compiled_effect.h"

namespace fxport::xlate {

// The GLSL for SV_VertexID (SPIRV-Cross's VertexIndex input).
std::string vertexIdExpression();
// `glsl` with the uniform vertexIdExpression() reads declared after its leading directives
// (#version, #extension: GLSL wants those before any declaration).
std::string withStartVertexDeclared(const std::string& glsl);

// The preprocessor lines that enable writing gl_Layer (`layer`) and gl_ViewportIndex (`viewport`)
// from `stage` (Vertex or Domain), or stop the compile with an #error saying what is missing.
std::vector<std::string> layerViewportExtensionLines(ShaderStage stage, bool layer, bool viewport);

// The separable `out gl_PerVertex { ... };` redeclaration of a shader writing gl_Layer or
// gl_ViewportIndex, kept for NVIDIA only: its compiler requires the redeclaration (C7592) and takes
// the extensions' outputs beside it, while Mesa counts them members of gl_PerVertex, so a
// redeclaration without them hides them (and Mesa needs none). GL_NV_viewport_array2 tells the two
// apart in the preprocessor.
std::string perVertexForLayerOutputs(const std::string& glsl);

}  // namespace fxport::xlate
