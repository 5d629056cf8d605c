// D3D11's [partitioning("pow2")]: integer partitioning whose tessellation factors are rounded up
// to a power of two (D3D11 functional spec, "Tessellator": pow2 clamps to [1, 64] and rounds up, as
// integer rounds up to a whole number). glslang's HLSL front end knows no pow2 ("unsupported
// partitioning type") and GL has no such spacing, so a pow2 hull shader is compiled as integer
// (GL's equal spacing; spirv_to_glsl gives the domain shader the same) and every factor it writes
// is rounded up first (to at most 64). GL clamps to [1, 64] as D3D does, and a factor of 0 still
// culls the patch.
#pragma once

#include <cstdint>
#include <vector>

#include "fx/fx_syntax.h"
#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

// `[partitioning("pow2")]` becomes `[partitioning("integer")]` in the text glslang reads (the
// entry's attributes are read from the original tokens, so the hull shader is still known as pow2).
std::vector<TextEdit> pow2PartitioningAsInteger(const EffectSyntax& syntax);

// Rounds each value stored to gl_TessLevelOuter / gl_TessLevelInner (a float element or a whole
// array) up to a power of two, 64 at most. For the legalised module of a pow2 hull shader (a pass
// of parsed_spirv.h: true when it changed the module).
bool roundTessFactorsToPowersOfTwo(ParsedSpirv& m);

}  // namespace fxport::xlate
