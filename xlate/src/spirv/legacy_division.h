// Division as D3D9 computes it. SM 2-3 have no divide instruction: fxc compiles a / b as
// a * rcp(b), and D3D9's multiply takes 0 times anything, infinity too, as 0. So 0 / 0 is 0 (vkd3d's
// float-comparison: "SM1-3 apparently treats '0/0' as zero"; 0 * rcp(0)), and so is inf / inf
// (inf * rcp(inf) = inf * 0), where IEEE's division gives NaN; every other quotient, its sign
// included, is IEEE's (vkd3d rcp: rcp(rcp(-0)) is -0). Every 32-bit float OpFDiv of an SM 2-3
// module becomes `(a == 0 && b == 0) || (|a| == inf && |b| == inf) ? 0 : a / b`, with ordered
// compares only (a driver may fold isnan away), before legalisation folds constants.
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

bool divisionAsRcpTimes(ParsedSpirv& m);

}  // namespace fxport::xlate
