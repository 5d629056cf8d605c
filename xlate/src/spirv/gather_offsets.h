// Gather with four texel offsets (`t.GatherRed(s, uv, o0, o1, o2, o3)`, SM 5): glslang makes one
// OpImageGather with ConstOffsets, which SPIRV-Cross writes as GLSL's textureGatherOffsets. Mesa's
// llvmpipe returns the wrong texels for it (each component reads the footprint's i0j0 texel at its
// offset; all zero offsets read texel (0, 0) everywhere) and so did the NVIDIA H200 driver on
// vkd3d's gather tests. fxc itself compiles the four-offset form to four gather4_po, one component
// of each, which is also how the GLSL specification defines textureGatherOffsets: the pass makes
// the same four gathers with one constant offset each and builds the result from component k of
// gather k.
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

// A pass of parsed_spirv.h; false (unchanged) when no gather has constant offsets.
bool gatherOffsetsAsFourGathers(ParsedSpirv& m);

}  // namespace fxport::xlate
