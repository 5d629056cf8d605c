// A geometry shader's per-vertex input struct holding SV_ClipDistanceN / SV_CullDistanceN
// (`triangle V input[3]` where V has `float3 d : SV_ClipDistance0`, as D3D10's FixedFuncEMU passes
// its clip planes through) crashes glslang (SIGSEGV while it splits the arrayed struct's
// clip/cull built-ins), whereas the same built-in as an arrayed parameter of its own
// (`triangle float3 d[3] : SV_ClipDistance0`) compiles. fxc takes both. So the entry gets:
//  - the struct without its clip/cull members (`fxport_gsin_V`, defined before the entry),
//  - one arrayed parameter `float c[n][K] : SV_ClipDistance0` holding every clip-distance
//    component of the struct in order of semantic index (and one such for the cull distances),
//    which is how the previous stage's outputs are packed (clip_distance_packing.h); one
//    parameter per member made glslang mislay the second one, and an arrayed float1 one failed,
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
