// Stages compiled apart, linked by semantic. xlate gives standard semantics (TEXCOORDn, COLORn ...)
// fixed GL locations, but numbers other names (RESULT, GAMMA ...) in the order one shader declares
// them, so a pixel shader compiled alone may read GAMMA at the location its vertex shader gave
// ALPHA. D3D matches stages by semantic; GL by location. This gives a reader's GLSL with each
// input moved to the location its writer gave the same semantic (the runtime makes that variant
// when the two differ), in the manner of the alpha-test variant (alpha_test.h).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "fxport/xlate/compiled_effect.h"

namespace fxport::xlate {

// `reader` with its inputs at `writerOutputs`' locations, semantic by semantic; an input the
// writer lacks keeps its location unless a moved one takes it (then it gets a free one).
// Empty when every shared semantic is already at the same location (nothing to change).
std::optional<CompiledShader> inputsLinkedTo(const CompiledShader& reader, const std::vector<Varying>& writerOutputs);

}  // namespace fxport::xlate
