// `!(a <= b)` as fxc compiles it for SM4-5: the `not` is folded into the opposite comparison
// (`a > b`), which is false when a or b is NaN, where `!(a <= b)` is true (vkd3d's
// float-comparison pins it: fxc's SM4-5 output differs from SM6's there). glslang emits an
// ordered comparison and OpLogicalNot; where the not is the comparison's only use, the comparison
// becomes the unordered one (`!unordered(a <= b)` is exactly ordered `a > b`), in place.
// Equality (`==`, `!=`) keeps its meaning either way and is left alone.
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

// A pass of parsed_spirv.h: true when it changed the module.
bool negatedComparisonsAsOpposites(ParsedSpirv& m);

}  // namespace fxport::xlate
