// A local array of textures or samplers initialized from global objects (`Texture2D q[2] = {tex1,
// tex2};`, vkd3d's initializer-objects): fxc resolves each element to its object at compile time;
// glslang emits a module with an id defined twice, which nothing downstream reads. Where every use
// of the array in its function is an element with a literal index (`q[1].Load(...)`), the
// declaration is blanked and each element becomes its object. Other uses are left to glslang.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> localObjectArraysResolved(const EffectSyntax& syntax);

}  // namespace fxport::xlate
