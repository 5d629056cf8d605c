// GLSL.std.450 SmoothStep and FClamp/SClamp/UClamp leave their result undefined when the bounds are
// reversed (edge0 >= edge1; min > max), where HLSL defines it by the arithmetic fxc compiles them
// to: smoothstep(a, b, x) is t * t * (3 - 2 * t) with t = saturate((x - a) / (b - a)), so
// `smoothstep(0.5, 0.0, d)` falls from 1 to 0 (OpenXRay's rain and gas-mask shaders); clamp(x, a, b)
// is min(max(x, a), b), so reversed bounds give b. glslang emits the GLSL.std.450 instructions
// for both; they are written out as fxc's arithmetic, on the unoptimised module. Bounds that are
// constants in order (saturate's 0 and 1, `smoothstep(0.2, 0.8, x)`) keep the instruction: its
// result is defined there and the same.
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

bool smoothstepAsFxcArithmetic(ParsedSpirv& m);
bool clampAsMinOfMax(ParsedSpirv& m);

}  // namespace fxport::xlate
