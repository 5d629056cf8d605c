// Step 4c, before legalisation: the clip and cull distances of hull and domain shaders, which
// glslang compiles only as user varyings (rewrite/tessellation_clip_semantics.h), made GL's
// built-ins where GL has them: a hull shader's inputs (gl_in[v].gl_ClipDistance, written by the
// vertex shader) and a domain shader's outputs (gl_ClipDistance, read by the rasteriser, a
// geometry or a pixel shader). The varying becomes a Private variable, filled from the built-in
// at the entry's start (inputs) or copied into it before each return (outputs); its components
// take the built-in's elements in order of semantic index, the order glslang and
// clip_distance_packing.h give the other stages' distances. A varying of another shape (an array)
// is left a user varying.
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

// A pass of parsed_spirv.h (any stage; only hull and domain shaders change).
bool tessellationClipDistances(ParsedSpirv& m);

}  // namespace fxport::xlate
