// A uniform's default value that holds a shader (`float f = {CompileShader(ps_2_0, fun())};`,
// `float4 f = {1, 2, compile ps_2_0 fun(), 4};`): fxc compiles it and writes no default value at
// all (vkd3d's effect-compile and default-values pin it). glslang knows no shader values
// ("'ps_2_0' : unknown variable"), so such an initializer is blanked before glslang and the
// uniform has no default, as with fxc. The same for a sampler_state among the values of a
// uniform that is no sampler (`float4 f = {sampler_state {...}, 1, 2, 3};`, vkd3d's
// sampler-state): the types do not match, and fxc discards the whole initializer (a sampler_state
// alone, not in a list, fxc refuses).
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> shaderValuedDefaultsDropped(const EffectSyntax& syntax);

}  // namespace fxport::xlate
