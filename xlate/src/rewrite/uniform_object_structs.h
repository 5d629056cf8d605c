// A uniform of a struct type holding objects and numbers (`struct Material { float4 color;
// Texture2D tex; SamplerState s; float2 uv; }; Material gMat;`, a global or a cbuffer member;
// vkd3d's object-field-offsets). fxc keeps the numbers in the constant buffer, at the offsets
// they would have without the objects, except that an object array or a struct of objects only
// still starts a register as any array or struct does; the objects take registers of their own.
// glslang flattens the whole variable into loose uniforms outside every constant buffer (no D3D
// offset: what a host writes into the buffer never reaches them) and refuses one in a cbuffer
// ("unable to find texture symbol"). So:
//  - the numbers get a struct of their own, `fxport_numbers_Material` (nested structs holding
//    objects likewise), the variable's type now; spirv/cbuffer_packing.h reads the original struct
//    to start a register where a dropped member did;
//  - each object becomes a global of its own, `fxport_gMat_tex` (arrays kept), declared before the
//    variable (before its cbuffer);
//  - `gMat.tex` (`gMat.inner.tex[1]`) becomes that global, and any other use of the whole variable
//    a call of a function that builds the original struct from both (`fxport_uniform_gMat()`).
// Not for arrays of such structs, nor structs holding arrays of structs with objects: left to glslang.
#pragma once

#include <string>
#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

inline constexpr const char* kNumbersStructPrefix = "fxport_numbers_";

std::vector<TextEdit> uniformObjectStructs(const EffectSyntax& syntax);

// For struct `s` (the original of a numbers struct): per member of the numbers struct, and one
// past the last, whether a dropped member before it starts a register (an object array, a struct
// of objects only).
std::vector<bool> numbersStructRegisterStarts(const EffectSyntax& syntax, const FxStruct& s);

}  // namespace fxport::xlate
