// D3D10/11 define what a resource access outside the resource does; GL leaves most of it
// undefined, and shaders rely on D3D's rule (a blur, SSAO or tiled-lighting shader that Loads its
// neighbours at the image border expects 0 there). The D3D rules (ld, ld_uav_typed, ld_structured,
// ld_raw): a texel coordinate, mip level, array slice or sample index out of range reads 0; a
// structured or byte-address buffer read past its end reads 0.
// - OpImageFetch (Texture*.Load, operator[], Buffer<T>) and OpImageRead (RWTexture*, RWBuffer
//   reads) become `inRange ? fetch : 0`, inRange comparing the coordinate (with its constant
//   offset) unsigned against OpImageQuerySize(Lod), the level against OpImageQueryLevels and the
//   sample against OpImageQuerySamples. D3D gives a format's missing channels their default (an
//   R32_FLOAT texture reads (0, 0, 0, 1)); the format is not known here, so every channel reads 0.
// - A scalar or vector OpLoad through an access chain into a buffer's runtime array (structured and
//   byte-address buffers) reads a clamped element and becomes `index < length ? value : 0`.
// - A store or atomic through such an access chain (RWStructuredBuffer, RWByteAddressBuffer) runs
//   only `if (index < length)`: D3D drops it, GL may write another buffer's memory. A dropped
//   atomic's original value reads 0; so does a whole struct or matrix element read past the end
//   (which OpSelect cannot choose before SPIR-V 1.4, so it is read under the same `if`). A loop
//   header holding such an access keeps its phis and merge instruction and branches to a new block
//   with the rest, which is split as any other block.
// Typed UAV stores and atomics out of range need nothing: GL defines them as D3D does (an invalid
// image store has no effect, an invalid image atomic updates nothing; GL 4.6 section 8.26).
// Run on the legalised module, after fetch offsets are folded into the coordinates.
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

// A pass of parsed_spirv.h; false (unchanged) when the module reads no image texel or buffer element.
bool outOfRangeReadsReadZero(ParsedSpirv& m);
// A pass of parsed_spirv.h; false (unchanged) when the module writes no buffer element (nor reads a composite one).
bool outOfRangeBufferWritesDropped(ParsedSpirv& m);

}  // namespace fxport::xlate
