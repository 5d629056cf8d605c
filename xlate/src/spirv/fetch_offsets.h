// Texture Load() with an offset the front end could not fold to a constant (a swizzle of a local
// vector holding literals: vkd3d's swizzle-constant-prop). fxc folds it; glslang leaves an
// OpImageFetch with a variable Offset, which GLSL's texelFetchOffset refuses ("must be a constant
// expression"). Load's offset only moves the texel read, so the fetch reads coordinate + offset
// instead (the array layer, when there is one, unmoved); out-of-range texels read 0 both ways.
#pragma once

#include <cstdint>
#include <vector>

namespace fxport::xlate {

// Rewrites the module; false (unchanged) when no fetch has a variable offset.
bool fetchOffsetsIntoCoordinates(std::vector<std::uint32_t>& words);

}  // namespace fxport::xlate
