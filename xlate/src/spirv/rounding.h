// HLSL's round() at shader model 4 and up is D3D's round_ne: halves go to the even integer
// (round(2.5) == 2, round(-0.5) == -0). glslang emits GLSL.std.450 RoundEven for it, except with
// its DX9-compatibility switch (tex2D/sampler2D sources, which fxport also compiles at ps_5_0:
// Torque3D's MLAA blend-weight shader), where it emits Round, whose halves GLSL leaves to the
// implementation. At SM 4+ every Round is made RoundEven; SM 2-3, which has no round instruction
// (fxc expands it with frc), is left as it is.
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

bool roundHalvesToEven(ParsedSpirv& m);

}  // namespace fxport::xlate
