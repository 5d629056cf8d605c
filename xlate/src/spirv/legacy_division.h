// Division as D3D9 computes it. SM 2-3 have no divide instruction: fxc compiles a / b as
// a * rcp(b), and D3D9's multiply takes 0 times anything, infinity too, as 0. So 0 / 0 is 0 (vkd3d's
// float-comparison: "SM1-3 apparently treats '0/0' as zero"), and so is anything over an
// infinity (rcp is 0 there), where IEEE's division gives NaN. Every 32-bit float OpFDiv of an
// SM 2-3 module becomes `a == 0 || |b| == inf ? 0 : a / b`, before legalisation folds constants.
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

bool divisionAsRcpTimes(ParsedSpirv& m);

}  // namespace fxport::xlate
