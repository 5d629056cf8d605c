// Step 4d: structured buffers laid out as D3D lays them out. D3D packs the elements of a
// StructuredBuffer<T> / RWStructuredBuffer<T> tightly: every member 4-byte aligned, no padding, so
// StructuredBuffer<float3> has a 12-byte stride and `struct { float2 x; float y; }` is 12 bytes.
// glslang lays the block out by GLSL's std430, which aligns a float3 (and a struct holding one, a
// float3 array element, a matrix row of three) to 16 bytes: the shader then reads every element
// but the first from the wrong place. GLSL 4.50 cannot declare a tighter layout, so this pass
// redeclares such a buffer's element as words, `struct { uint w[stride / 4]; }` with the D3D
// stride, and turns each access into word loads and stores (bitcast to the member's type) at the
// D3D offsets. Buffers whose std430 layout already is D3D's are left as they are, and so is a
// buffer used in a way the pass does not know (an atomic on an int member, a pointer copied).
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

// The stride GetDimensions reports for such a buffer: glslang stores its std430 stride as a
// constant; D3D's replaces it. Run on the unoptimised module, before forwarding hides the store.
// Passes of parsed_spirv.h: true when they changed the module.
bool structuredBufferStridesAsD3D(ParsedSpirv& m);

// Repacks the structured buffers of `m` (a legalised module).
bool packStructuredBuffersTightly(ParsedSpirv& m);

}  // namespace fxport::xlate
