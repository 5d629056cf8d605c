// A geometry shader's per-vertex input struct holding SV_ClipDistanceN / SV_CullDistanceN
// (`triangle V input[3]` where V has `float3 d : SV_ClipDistance0`, as D3D10's FixedFuncEMU passes
// its clip planes through) crashes glslang (SIGSEGV while it splits the arrayed struct's
// clip/cull built-ins), whereas the same built-in as an arrayed parameter of its own
// (`triangle float3 d[3] : SV_ClipDistance0`) compiles. fxc takes both. So the entry gets:
//  - the struct without its clip/cull members (`fxport_gsin_V`, defined before the entry),
//  - one arrayed parameter per clip/cull member with the member's type and semantic (a scalar
//    as float[n][1], so gl_in's array is sized as the previous stage writes it),
//  - and, first in the body, the original `V input[3]` assembled from them, so the body reads
//    `input[i]` (whole-struct copies included) as written.
// Everything stays on the lines where it was.
#pragma once

#include <string>
#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

// The edits so for `entry` (a geometry shader entry); none when no input parameter needs them.
std::vector<TextEdit> geometryEntryClipInputs(const EffectSyntax& syntax, const std::string& entry);

}  // namespace fxport::xlate
