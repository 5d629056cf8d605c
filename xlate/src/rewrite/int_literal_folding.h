// Constant expressions of unsuffixed integer literals (`3000000000 + 3000000000`) as fxc folds
// them: each literal is the int its low 32 bits spell (`3000000000` is -1294967296), the
// arithmetic is exact (fxc folds in double precision) and the result becomes an int as x86's
// truncating conversion makes it: INT_MIN (0x80000000) where it is out of range. glslang wraps
// every step instead, so `int x = 3000000000 + 3000000000;` is 1705032704 to it and INT_MIN to
// fxc, at every shader model (vkd3d's sm1-const-folding pins it; `uint x = ...` then reads
// 2147483648). An expression whose steps all stay in range means the same to both and stays as
// written; so does any with a suffixed, float or non-literal operand. Judged on whole operands:
// a run of literals, + - * / % and parentheses between `=`, `(`, `,`, `return` ... and `;`, `)`,
// `,` ...
#pragma once

#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

std::vector<TextEdit> overflowingIntFoldsAsFxc(const EffectSyntax& syntax);

}  // namespace fxport::xlate
