// `T.sample[s][p]` on a Texture2DMS or Texture2DMSArray: fxc reads sample s of the texel at p, as
// `T.Load(p, s)` does (MAGE's deferred_input.hlsli and msaa.hlsli, RenderDoc's
// d3d12_pixelhistory.hlsl). glslang has no such operator ("'sample' : unexpected operator on
// texture type"), so the indexer is written as that Load. Only where the object's type is evident
// (method_receivers.h: a global, a parameter, a struct's member, subscripts).
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> sampleIndexersAsLoads(const EffectSyntax& syntax);

}  // namespace fxport::xlate
