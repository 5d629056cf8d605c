// A global array of textures with more than one dimension (`Texture2D tex[2][2];`, vkd3d's
// combined-samplers): fxc gives its elements consecutive t registers, the last index running
// fastest; glslang finds no texture behind `tex[1][1].Sample(...)` ("unable to find texture
// symbol"). Where every use indexes all dimensions, the array is declared with one dimension of
// as many elements and `tex[i][j]` becomes `tex[(i) * 2 + (j)]`: the same element on the same
// register.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> objectArraysFlattened(const EffectSyntax& syntax);

}  // namespace fxport::xlate
