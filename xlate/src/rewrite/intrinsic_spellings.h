// HLSL intrinsics that glslang's HLSL front end declares under another name: D3D's
// EvaluateAttributeCentroid(x) is glslang's EvaluateAttributeAtCentroid(x) (hlslParseables), so
// the D3D spelling was refused as an unknown function. Calls are respelled, unless the effect
// defines a function of the D3D name itself. Texture methods likewise: GatherCmpGreen/Blue/Alpha,
// which glslang does not implement, are GatherCmpRed (see the .cpp).
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> intrinsicsAsGlslangSpellsThem(const EffectSyntax& syntax);

}  // namespace fxport::xlate
