// Step 4c: constant buffers laid out as D3D packs them, so the byte a D3D host writes at a
// variable's D3D offset is the byte the shader reads (ID3D11 UpdateSubresource, D3DReflect, the
// vkd3d suite's `uniform N`), and XNA's EffectParameter offsets are D3D's too.
//
// D3D's cbuffer packing: a scalar or vector starts where the previous member ended unless it would
// cross a 16-byte register, then it starts the next register; an array, matrix or struct starts a
// register; an array element takes whole registers but the last; a column_major RxC matrix is C
// registers of R floats (row_major: R of C); the next member may use the tail of the last register
// of an array, matrix or struct. packoffset(cN.y) places a cbuffer member, register(cN) a $Global.
//
// glslang lays $Global out with std140 and user cbuffers half the HLSL way (the tail of an array's
// last register stays unused; packoffset only where it keeps offsets increasing). packConstantBuffers
// re-decorates every block with D3D's offsets; where GLSL cannot declare those (a float3 at c0.y, a
// scalar in an array's last register, offsets out of order) flattenConstantBuffer declares the block
// as `uvec4 registers[N]` and rewrites every read of it into register loads and bit casts.
// Tests: xlate.CbufferPacking.*, runtime CbufferPacking.*, conformance cbuffer.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "glsl/spirv_to_glsl.h"
#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

struct EffectSyntax;

struct PackedBlock {
    std::uint32_t variable = 0;           // the block's OpVariable
    std::uint32_t type = 0;               // its struct type (before flattening)
    std::string name;                     // "$Global" or the cbuffer's name
    int size = 0;                         // bytes, a multiple of 16
    std::vector<UniformMember> members;   // at their D3D offsets
    bool glslDeclarable = false;          // GLSL can declare these offsets (layout(offset = N))
    bool flattened = false;               // declared as uvec4 registers[size / 16]
    // Struct types that are numbers-only twins (rewrite/uniform_object_structs.h): per member, and
    // one past the last, whether a register starts there for a dropped object member.
    std::map<std::uint32_t, std::vector<bool>> registerStarts;
    // Flattened blocks only (SPIRV-Cross sees one member then): the byte ranges the shader reads
    // (block = -1, for the caller to fill) and the members they belong to.
    std::vector<UniformRange> rangesRead;
    std::vector<std::string> membersRead;
};

// Re-decorates the Offset of every uniform block member (and the ArrayStride of arrays of structs
// in one) with D3D's packing; `syntax` gives packoffset and register(cN). The fxport-internal block
// is left as it is. `spirv` is freshly parsed (ParsedSpirv::ids() holds).
std::vector<PackedBlock> packConstantBuffers(ParsedSpirv& spirv, const EffectSyntax& syntax);

// Declares `block` as an array of uvec4 registers and rewrites its reads; false (and the module
// as it was) where the module uses the block otherwise than through access chains and loads.
// `spirv` is freshly parsed (reparse() after the decorations above or another flattening).
bool flattenConstantBuffer(ParsedSpirv& spirv, PackedBlock& block);

}  // namespace fxport::xlate
