// A struct or array value used where fxc converts it to another struct or array type: implicitly
// where the two match component for component in type (componentwise-equal: `return In;` from a
// function returning another struct with the same members, `B b = a;`, `b = a;`, passing `a` to a
// `B` parameter, and between a struct and an array: Intel AOIT's `data.color = B[addr];` of a
// `StructuredBuffer<C>`, `struct C { uint4 color[N]; }`, and its store `RWB[addr] = a;`), and
// explicitly by a cast `(B) a` in any expression (as many components or more, each converted).
// The value may be any expression whose type expression_types.h knows (a variable, a member, a
// structured buffer's element); Microsoft's Xbox-ATG-Samples SimpleTexturePC VertexShader.hlsl
// returns its input struct as its output struct; vkd3d's cast-componentwise-equal and -compatible
// pin the rules (fxc compiles what they mark fail(sm>=6)). glslang refuses these ("type does not
// match", "could not create assignment", "no matching overloaded function"), so the value goes
// through a generated function that builds the target one component at a time, defined before the
// first function that needs it: a struct is its value (`fxport_convert_Vertex_to_Interpolants(In)`);
// an array, which no function returns, its first, out, parameter (`d.color = B[0];` becomes
// `fxport_convert_C_to_uint4_1(d.color, B[0]);`, `uint4 a[1] = B[1];` becomes `uint4 a[1];
// fxport_convert_C_to_uint4_1(a, B[1]);`). Either way each side is evaluated once.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> aggregateConversions(const EffectSyntax& syntax);

}  // namespace fxport::xlate
