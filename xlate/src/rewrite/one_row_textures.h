// DX9 one-dimensional sampling on GL. D3D9 has no 1D textures: what a `sampler1D` reads is a 2D
// texture of one row (XNA has no Texture1D either; Nez's PaletteCycler and toon-shading ramps
// bind a Texture2D of height 1). A GL sampler1D reads only the unit's 1D target, where nothing is
// bound, so it read black. The DX9 sampler is declared a sampler2D (fx_rewrite.cpp) and each
// tex1D, tex1Dlod, tex1Dbias, tex1Dproj and tex1Dgrad becomes a helper that samples the middle of
// the row: exact for one-row textures, whatever the filter and address modes.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> oneDimensionalSamplingAsRows(const EffectSyntax& syntax);

}  // namespace fxport::xlate
