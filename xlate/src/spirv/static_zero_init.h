// A file-scope `static` variable without an initializer starts at zero in D3D (fxc zero-fills
// it; vkd3d's static-initializer pins `static struct {float4 x; float3 y;} x;` reading 0 and
// `static uint i; 1 / i` refused as a division by zero). glslang declares it as a Private
// variable without an initializer, and a GLSL global without one is undefined: llvmpipe read
// garbage. Each such variable of numeric, bool, struct or array type gets OpConstantNull as its
// initializer, before the constant-division check and the optimiser see the module.
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

// A pass of parsed_spirv.h: false (unchanged) when no Private variable lacks an initializer.
bool staticVariablesStartAtZero(ParsedSpirv& m);

}  // namespace fxport::xlate
