// The texture units of DX10 texture objects (the GL units their samplers get; the D3D11 front end
// maps its t# slots onto them): a `register(tN)` reserves N and, for an array, the units of all its
// elements; the others get, in declaration order, the first free run of units for all their
// elements, as fxc hands out t registers. An array takes one unit per element because GL binds an
// array of samplers to consecutive units: one unit for `Texture2D t[2][2]` let the next texture's
// unit collide with t's second element.
#pragma once

#include <map>
#include <string>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

// The registers texture `t` takes: the product of its array sizes, 1 for a single texture.
int textureElements(const EffectSyntax& syntax, const FxTexture& t);

// The first t register of each DX10 texture object that gets one.
std::map<std::string, int> textureRegisters(const EffectSyntax& syntax);

}  // namespace fxport::xlate
