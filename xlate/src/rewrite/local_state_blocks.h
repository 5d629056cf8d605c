// A state block on a local variable: `float b { foo = bar; };`, `float c {}, d = 1;`,
// `struct {int a;} s {foo = bar;};`. fxc parses a `{ ... }` block after any variable's name and
// drops it (vkd3d's state-block-syntax pins it in a function body); fx_parser.cpp drops those on
// globals, and glslang stops at one in a body ("';' : Expected"). In a body, such a block is blanked.
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> localStateBlocksDropped(const EffectSyntax& syntax);

}  // namespace fxport::xlate
