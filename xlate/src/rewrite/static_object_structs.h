// A file-scope static struct of objects initialized from global objects: OGRE's
// HLSL_SM4Support.hlsl (`SAMPLER2D(name, reg)` on SM4) declares `struct Sampler2D { Texture2D t;
// SamplerState s; };` and `static Sampler2D name = {nameTex, nameState};`, passed to its tex2D
// overloads. fxc resolves the members to the objects at compile time; glslang leaves a private
// variable holding images, which SPIRV-Cross cannot translate. When the struct's members are all
// objects, each initializer element a global object and the variable never assigned:
//  - `name.member` becomes the member's object (`name.t` -> `nameTex`);
//  - any other use becomes a call of a generated function that builds the struct from the objects
//    (`tex2D(name, uv)` -> `tex2D(fxport_static_name(), uv)`), which glslang inlines;
//  - the declaration becomes that function.
// Only in functions after the declaration that have no parameter or local of that name.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> staticObjectStructs(const EffectSyntax& syntax);

}  // namespace fxport::xlate
