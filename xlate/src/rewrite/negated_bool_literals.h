// `-true` as fxc reads it: the bool converts to the int 1 and is negated (`max(-true, -2)` is -1;
// vkd3d's max-min pins it). glslang's HLSL front end stops at a unary minus on a bool literal
// ("'function call arguments' : Expected"). Where `-` is a unary minus before `true` or `false`,
// the literal is spelled as that int (`-1`, `-0`).
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> negatedBoolLiteralsAsInts(const EffectSyntax& syntax);

}  // namespace fxport::xlate
