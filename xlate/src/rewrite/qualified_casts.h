// A cast whose type carries `const`: Source SDK's common_vs_fxc.h writes
// `mul3x3(modelNormal, (const float3x3)cModel[0])` in every vertex shader. fxc reads the qualifier
// as nothing (a cast's value is no variable, so const says nothing about it); glslang's HLSL front
// end does not parse a qualifier there ("'expression' : Expected"). `( const TYPE )`, TYPE one
// name or a `vector<...>`/`matrix<...>`, loses its `const`.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> castQualifiersDropped(const EffectSyntax& syntax);

}  // namespace fxport::xlate
