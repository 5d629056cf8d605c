// `.Length` of a texture or buffer object (SM4 and SM5): its size as uint, uint2 or uint3 (width;
// width, height or elements; width, height and depth or elements), without mip or sample counts
// (vkd3d's length-property pins it). glslang knows no such property ("unexpected operator on
// texture type"). Each object whose Length a function reads gets a helper before that function,
// `uint2 fxport_Length_t() { uint a0, a1; t.GetDimensions(a0, a1); return uint2(a0, a1); }`, and
// `t.Length` becomes `fxport_Length_t()`. Cube textures have no Length (fxc's error, and glslang's).
// Shader models 2 and 3 have no Length at all: findLengthPropertyErrors says so (fxc X3018).
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> lengthPropertiesAsCalls(const EffectSyntax& syntax);

}  // namespace fxport::xlate
