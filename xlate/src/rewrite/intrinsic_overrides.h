// A function of the effect named like an intrinsic (`float2 max(float2 a, float2 b)`) is what fxc
// calls wherever the arguments convert to its parameters: `max(0.1, 0.2)` is that max of
// float2(0.1) and float2(0.2); the intrinsic only where they do not (`max(float2, float2)` against
// a user `max(float2, float3)`; vkd3d's intrinsic-override pins both). glslang takes its built-in
// wherever it matches better. The effect's functions of such a name are renamed
// `fxport_user_<name>`, and so are the calls with as many arguments as one of them takes, unless
// the arguments' types are evident (expression_types.h) and convert to none of them.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> intrinsicOverrides(const EffectSyntax& syntax);

}  // namespace fxport::xlate
