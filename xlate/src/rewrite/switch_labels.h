// `switch` as fxc takes it (vkd3d's switch pins it): a case label may be a float literal, read as
// the integer it truncates to (`case 2.1f:` is `case 2:`), and at shader model 4 and up the
// selector may be a float, converted to int. glslang refuses both ("duplicated value": every float
// label reads as 0; "condition must be a scalar integer expression"). The labels are respelled as
// integers, and a selector that is evidently a float (expression_types.h) becomes `int(...)`.
// At shader models 2 and 3 fxc refuses a float selector: findSwitchSelectorErrors says so.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> switchLabelsAsIntegers(const EffectSyntax& syntax);

}  // namespace fxport::xlate
