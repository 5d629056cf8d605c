// Clip and cull distances in hull and domain shaders. fxc takes SV_ClipDistanceN / SV_CullDistanceN
// on every stage's inputs and outputs (Wicked Engine's tessellated objects pass `float clip :
// SV_ClipDistance0` from the vertex shader through hull and domain shader); glslang 12 refuses
// them outside vertex, geometry and pixel shaders ("clip/cull not currently implemented for this
// stage"). So in a hull or domain shader's text every such semantic becomes a user semantic
// (FXPORT_CLIPDISTANCEn / FXPORT_CULLDISTANCEn), which glslang compiles as an ordinary varying;
// the SPIR-V pass spirv/tessellation_clip_distances.h then turns those that meet GL's built-ins
// (a hull shader's inputs, a domain shader's outputs) back into gl_ClipDistance / gl_CullDistance.
// Between hull and domain shader they stay user varyings: D3D clips only after the last stage.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

inline constexpr const char* kTessellationClipSemantic = "FXPORT_CLIPDISTANCE";
inline constexpr const char* kTessellationCullSemantic = "FXPORT_CULLDISTANCE";

// The edits that respell every `: SV_ClipDistanceN` / `: SV_CullDistanceN` semantic of the text.
std::vector<TextEdit> tessellationClipSemantics(const EffectSyntax& syntax);

}  // namespace fxport::xlate
