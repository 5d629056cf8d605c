// A static texture or sampler variable at file scope that only ever holds one global object:
// `static Texture2D tex = real_tex;`, or `static Texture2D tex;` with `tex = real_tex;` in the
// functions. fxc resolves such variables to the object at compile time; GLSL has no variables of
// opaque types to assign (the driver refuses `texture2D tex; tex = real_tex;`; vkd3d's
// static-initializer pins both forms). When every assignment to it (its initializer included)
// names the same global object, the variable becomes that object: its declaration and the
// assignments are blanked and its uses renamed. Any other use is left to glslang.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> staticObjectAliases(const EffectSyntax& syntax);

}  // namespace fxport::xlate
