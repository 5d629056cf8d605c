// A struct or array variable used where fxc converts it to another struct type: implicitly where
// the two match component for component in type (componentwise-equal: `return In;` from a function
// returning another struct with the same members, `B b = a;`, passing `a` to a `B` parameter), and
// explicitly by a cast `(B) a` in any expression (as many components or more, each converted).
// Microsoft's Xbox-ATG-Samples SimpleTexturePC VertexShader.hlsl returns its input struct as its
// output struct; vkd3d's cast-componentwise-equal and -compatible pin the rules (fxc compiles what
// they mark fail(sm>=6)). glslang refuses these ("type does not match", "no matching overloaded
// function"), so the variable is passed through a generated function that builds the target
// struct one component at a time (`fxport_convert_Vertex_to_Interpolants(In)`), defined before the
// first function that needs it. Plain assignment `b = a;` is componentwise_casts.h's.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> aggregateConversions(const EffectSyntax& syntax);

}  // namespace fxport::xlate
