// INTERNAL: D3D's rules for one compiled shader: which b#, t# and s# slots its constant buffers,
// textures and samplers take (an explicit register() holds; the others get the lowest free slot
// of their kind in declaration order among what the shader uses, $Globals first, as fxc does),
// where each cbuffer variable lives under D3D's packing rules, and which GL binding or unit of
// fxport's translation each slot feeds.
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "fxport/xlate/compiled_effect.h"

namespace fxport::d3d11 {

// A cbuffer variable placed by D3D's packing: scalars and vectors do not straddle a 16-byte
// register, arrays, matrices and structs start one; an array element takes whole registers but
// the last; a column_major RxC matrix is C registers of R floats (row_major: R of C).
struct PackedVariable {
    int parameter = -1;  // index in CompiledEffect::parameters
    int offset = 0;      // bytes from the cbuffer's start
    int size = 0;        // bytes, without the padding after the last component
};
std::vector<PackedVariable> packCbuffer(const xlate::CompiledEffect& effect, int block);
int packedSize(const xlate::Parameter& p);  // D3D size in bytes of one variable

struct CbufferBinding {
    std::string name;  // "$Globals" or the cbuffer's name
    int block = 0;     // CompiledEffect::uniformBlocks index
    int blockBinding = 0;
    int slot = 0;      // b#
    int size = 0;      // D3D size, a multiple of 16
};
struct ResourceBinding {
    std::string name;
    int slot = 0;  // t# or s#
    xlate::TextureKind kind = xlate::TextureKind::Texture2D;
};
struct SamplerUnit {  // one GL texture unit the shader samples: fed by t# through s#
    int glUnit = 0;
    int textureSlot = -1;
    int samplerSlot = -1;  // -1: no sampler (Load) -- a default linear sampler
};
struct ShaderBindings {
    int shader = 0;
    std::vector<CbufferBinding> cbuffers;  // by slot
    std::vector<ResourceBinding> textures;  // by slot
    std::vector<ResourceBinding> samplers;  // by slot
    std::vector<SamplerUnit> units;
};

ShaderBindings bindingsOf(const xlate::CompiledEffect& effect, int shader);
// Empty, or a sentence naming the first cbuffer variable that fxport's GL layout places elsewhere
// than D3D packs it (only a block the translation had to re-lay out with std140, see
// UniformBlock::d3dPacking): a host's bytes would be misread, so no shader is made.
std::string layoutMismatch(const xlate::CompiledEffect& effect, const ShaderBindings& bindings);

}  // namespace fxport::d3d11
