// Step 4c: SV_ClipDistance / SV_CullDistance packed the way GL needs them. glslang gives semantic
// index n the gl_ClipDistance elements from 4n (D3D's register layout): `float2 a :
// SV_ClipDistance0; float3 b : SV_ClipDistance1` becomes gl_ClipDistance[7] with elements 2 and 3
// never written. GL clips by every enabled plane and counts the declared size against its limit of
// 8 clip and cull distances together, so the holes cost planes D3D never had (5 clip + 3 cull
// distances fit D3D11 and fail to link in GL). This pass renumbers the elements a shader uses to
// 0..n-1 in their order and shrinks the arrays to n; a shader that indexes them dynamically or
// copies them whole keeps glslang's layout.
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

// Packs the ClipDistance and CullDistance built-ins of `m` (a legalised module): a pass of
// parsed_spirv.h, true when it changed the module.
bool packClipCullDistances(ParsedSpirv& m);

}  // namespace fxport::xlate
