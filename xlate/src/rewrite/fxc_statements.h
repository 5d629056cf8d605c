// What fxc accepts inside function bodies that glslang does not, made plain HLSL by text edits on the
// preprocessed effect (lines kept): a shader writing to a global uniform (fxc gives the shader its
// own copy), a `for` header's variable used after its loop (fxc's enclosing scope), a constructor
// as an assignment target (`float4(a.xy, b.zw) = v;`).
#pragma once

#include <string>
#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

// `Scale *= 2;` on a uniform: `static T fxport_copy_Scale = Scale;` after its declaration, and the
// functions that do not hide it use the copy.
void copyAssignedUniforms(const EffectSyntax& syntax, std::vector<TextEdit>& edits);

// `for (int i = 0; ...) ...; use(i);`: the declaration moves in front of the loop.
void hoistLoopVariablesUsedAfterTheLoop(const EffectSyntax& syntax, std::vector<TextEdit>& edits);

// `float4(a, b) = v;` -> `{ float4 fxport_parts0 = v; a = fxport_parts0.xy; b = fxport_parts0.zw; }`.
void splitConstructorAssignments(const std::string& text, const EffectSyntax& syntax, std::vector<TextEdit>& edits);

}  // namespace fxport::xlate
