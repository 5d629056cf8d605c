// Texture Load() with an offset the front end could not fold to a constant (a swizzle of a local
// vector holding literals: vkd3d's swizzle-constant-prop). fxc folds it; glslang leaves an
// OpImageFetch with a variable Offset, which GLSL's texelFetchOffset refuses ("must be a constant
// expression"). Load's offset only moves the texel read, so the fetch reads coordinate + offset
// instead (the array layer, when there is one, unmoved); out-of-range texels read 0 both ways.
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

// A pass of parsed_spirv.h; false (unchanged) when no fetch has a variable offset.
bool fetchOffsetsIntoCoordinates(ParsedSpirv& m);

}  // namespace fxport::xlate
