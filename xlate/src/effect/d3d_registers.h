// The t# and s# registers fxc gives the textures and samplers one D3D10+ shader uses
// (SamplerBinding::textureRegister / samplerRegister), for a D3D11 front end to bind slot N where
// D3D would; and the s# of an SM 1-3 shader's samplers (assignD3d9SamplerRegisters). vkd3d's
// texture-ordering and combined-samplers pin fxc's rules:
//  - a register(tN) / register(sN) holds, and fxc keeps it reserved even where it is unused; one
//    of another class (a texture's register(s0)) is ignored, and so is one for another profile
//    (reservedRegister);
//  - textures: first those fxc makes for DX9 samplers (`tex2D(sam, uv)` at SM4: one texture per
//    sampler, an array's texture as wide as its "bind count", the last element used + 1), by
//    decreasing bind count, ties in the order the code first samples them; then the declared
//    texture objects in declaration order, an array taking all its elements' registers;
//  - samplers: sampler arrays (as wide as their bind count) in declaration order, then the single
//    samplers in declaration order.
// Each takes the lowest free run of registers. The bindings are fxport's rewritten names: a DX9
// sampler array's element `sam_fxport_1` (sampler_array_elements.h) and the texture made for a
// sampler that is used both ways, `sam_fxport_texture2D` (sampler_textures.h), name their origin.
#pragma once

#include <cstdint>
#include <vector>

#include "fx/fx_syntax.h"
#include "fxport/xlate/compiled_effect.h"

namespace fxport::xlate {

// `firstUse`: per binding, a key that orders the bindings by the code's first use of them.
// `bufferRegisters`: t registers structured and raw buffers of the shader already hold.
void assignD3dRegisters(std::vector<SamplerBinding>& bindings, const std::vector<std::uint32_t>& firstUse,
                        const EffectSyntax& syntax, const std::vector<int>& bufferRegisters, const ShaderProfile& target);

// SM 1-3: the sampler register (s#, also the texture stage) fxc gives each binding, in both
// textureRegister and samplerRegister. vkd3d's combined-samplers pins the order: a register(sN)
// holds; `tex.Sample(sam, uv)` makes a combined sampler per sampler and texture, as wide as the
// texture (array); the rest take the lowest free run by decreasing width, ties the combined ones
// first (in their samplers' declaration order), then the DX9 samplers in declaration order (an
// array as wide as its last used element + 1). Samplers the shader does not sample take none. A
// shader that would pass s15 (which fxc refuses; fxport's GL units go further) gets none (-1).
void assignD3d9SamplerRegisters(std::vector<SamplerBinding>& bindings, const EffectSyntax& syntax, const ShaderProfile& target);

// The register of class `registerClass` ('t', 's') that `registers` bind an object at in a shader
// compiled for `target`; -1 for none. As vkd3d's register-reservations-profile pins fxc (SM4-5):
// a reservation applies without a profile, with the shader's stage (`ps`), with its exact profile
// (`ps_4_0`), and `ps_4_0` in the later SM4-5 profiles too (`ps_4_1` does not in ps_5_0); among
// those that apply the last one written wins; `ps[5]` binds nothing.
int reservedRegister(const std::vector<FxRegister>& registers, char registerClass, const ShaderProfile& target);

}  // namespace fxport::xlate
