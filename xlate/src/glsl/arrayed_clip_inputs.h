// A geometry shader's input clip/cull distances as GLSL spells them. glslang gives the HLSL input
// (`triangle float3 d[3] : SV_ClipDistance0`) a ClipDistance built-in outside any block, an array
// per vertex, and SPIRV-Cross writes its reads `gl_ClipDistance[v][i]`; in a GLSL geometry shader
// that name is the output's `float[]`, so GL refuses the second index ("left of '[' is not of type
// array"). The per-vertex input is `gl_in[v].gl_ClipDistance[i]` (SPIRV-Cross already declares it in
// gl_in's block), so the doubly indexed reads are respelled so, and a whole copy of the input
// (`float p[3][1] = gl_ClipDistance;`) is built from gl_in element by element.
#pragma once

#include <string>

namespace fxport::xlate {

// clipSize / cullSize: the per-vertex element counts of the ClipDistance / CullDistance inputs
// (0: none). SPIRV-Cross sizes gl_in's members by the wrong one of the two array dimensions.
std::string geometryClipInputsRespelled(const std::string& glsl, int clipSize, int cullSize);

}  // namespace fxport::xlate
