// UAV declarations whose element type glslang's HLSL front end cannot declare, a matrix or a
// struct of at most four numeric components (`RWTexture1D<float2x2> u2;`, `RWTexture2D<struct s>
// u3;`: "scalar, vector, or struct type expected") or a double or double2 (four 32-bit words;
// "basic type in texture: Unimplemented", uav-rwbuffer L69), and that no function reads or
// writes: fxc compiles them and drops them (an
// unused resource gets no register), so their declarations are blanked before glslang (vkd3d's
// uav-rwtexture declares one of each type and writes the first). A used one stays, for glslang
// to refuse.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> unusedUavsDropped(const EffectSyntax& syntax);

}  // namespace fxport::xlate
