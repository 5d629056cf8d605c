// Objects declared inside a cbuffer or tbuffer (`cbuffer b { float4 a; Texture2D tex; sampler s; }`):
// fxc takes them, and they are the resources they would be outside it — a packoffset on one
// changes no register (vkd3d's cbuffer tests). glslang keeps them as members of the uniform block,
// which GLSL refuses. Each moves out, before the `cbuffer` keyword on that keyword's line, without
// its packoffset and without a register of another class than its own (`Texture2D t :
// register(s2)` is no sampler; fxc gives it a t register of its own).
// A `static` variable there is no member either (VarianceShadows11: `static float d[8] =
// (float[8])data;` after `float4 data[2];`); glslang cannot see the members from its initializer
// ("unknown variable"). It moves after the body, onto the closing brace's line.
// Runs on the preprocessed text, before the parser; every other line stays where it was.
#pragma once

#include <string>

namespace fxport::xlate {

std::string nonMembersMovedOutOfCbuffers(const std::string& preprocessed);

}  // namespace fxport::xlate
