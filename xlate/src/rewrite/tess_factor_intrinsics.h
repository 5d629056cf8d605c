// The hull-shader intrinsics that turn raw tessellation factors into the ones the tessellator
// takes -- ProcessTriTessFactors{Avg,Max,Min}, ProcessQuadTessFactors{Avg,Max,Min},
// Process2DQuadTessFactors{Avg,Max,Min}, ProcessIsolineTessFactors. glslang 12 declares them
// but gives them no body, so their out arguments stay undefined (a hull shader's factors were
// garbage, silently). Calls are renamed to helper functions with D3D's arithmetic, as DXC lowers
// them (HLOperationLower.cpp): raw edge factors clamped to the partitioning's range and rounded up
// (integer: to a whole number, pow2: to a power of two, fractional: not rounded); the inside
// factor is the average, maximum or minimum of the edge factors (each at least 1), scaled by the
// inside scale (clamped to [0, 1]), clamped and rounded the same way, with fractional_odd's rule
// for small factors. The partitioning is the compiled hull shader's: hlsl_to_spirv defines
// FXPORT_PARTITIONING for glslang (0 integer, 1 pow2, 2 fractional_odd, 3 fractional_even).
// The helpers go before the first function, on its line, so line numbers hold; an effect that
// defines a function of one of these names keeps its calls.
#pragma once

#include <string>
#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> tessFactorIntrinsics(const EffectSyntax& syntax);

// The FXPORT_PARTITIONING value of a hull shader's [partitioning("...")] (0 for none).
int partitioningCode(const std::string& partitioning);

}  // namespace fxport::xlate
