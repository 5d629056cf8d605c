// The entry attributes of the D3D11 stages -- compute [numthreads], hull [domain] [partitioning]
// [outputtopology] [outputcontrolpoints] [patchconstantfunc], domain [domain] -- read from the
// entry's attribute text and checked as fxc checks them, so that a missing or malformed one is a
// located error rather than whatever glslang makes of it. The SPIR-V's LocalSize (the evaluated
// numthreads) is checked against D3D's limits by checkThreadGroupSize.
#pragma once

#include <array>
#include <string>

#include "fx/fx_syntax.h"
#include "fxport/xlate/compiled_effect.h"

namespace fxport::xlate {

// What fxc would say about `entry`'s attributes for `profile` (a compute, hull or domain
// profile); empty when they are fine. `out` gets the tessellation attributes of hull and domain
// shaders (and the control-point counts of their InputPatch/OutputPatch parameters).
std::string checkStageAttributes(const EffectSyntax& syntax, const FxFunction& entry, const ShaderProfile& profile, Tessellation& out);

// Whether `entry` carries attribute `name` (`[earlydepthstencil]`), in the case written, as fxc
// matches attribute names.
bool hasAttribute(const FxFunction& entry, const std::string& name);

// D3D11's thread-group limits (cs_5_0: x, y <= 1024, z <= 64, x*y*z <= 1024; cs_4_x: x, y <= 768,
// z == 1, x*y*z <= 768); empty when `size` is within them.
std::string checkThreadGroupSize(const std::array<int, 3>& size, const ShaderProfile& profile);

}  // namespace fxport::xlate
