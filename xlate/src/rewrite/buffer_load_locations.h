// `Buffer.Load(location)` with a vector (or matrix) location: fxc converts the argument to the int
// parameter as it converts any argument, keeping the first component (an implicit truncation,
// warning X3206): `buffer.Load(float2(2, 9999))` reads element 2 (vkd3d's srv-buffers L95). glslang
// finds no overload ("'__BI_Load' : no matching overloaded function found"). So such a location
// becomes its first component, `(location).x` (`._m00` for a matrix), which glslang converts to int
// as fxc does. Only where the location's type is evident (expression_types.h); a Buffer's or an
// RWBuffer's Load only (a texture's Load takes a vector, which glslang truncates itself).
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> bufferLoadLocationsAsScalars(const EffectSyntax& syntax);

}  // namespace fxport::xlate
