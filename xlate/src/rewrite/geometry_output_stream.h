// A geometry shader entry's output streams as fxc takes them, respelled for glslang:
//  - a stream parameter the entry never mentions is not validated by fxc (`PointStream` beside an
//    unused `TriangleStream` is fine); glslang declares an output primitive for each ("output
//    primitive geometry redefinition"), so unused streams leave the parameter list;
//  - an entry without an output stream (`[maxvertexcount(4)] void main(point V v[1]) {}`) is valid:
//    fxc compiles a shader that emits nothing. GLSL needs an output primitive (glslang: "At least
//    one shader must specify an output layout primitive"), so it gets a stream it never appends to:
//    `inout PointStream<float4> fxport_noOutput`.
#pragma once

#include <string>
#include <vector>

#include "fx/fx_syntax.h"

namespace fxport::xlate {

// The edit respelling the parameter list of `entry` (a geometry shader entry) so; none when nothing
// changes or the entry is not found.
std::vector<TextEdit> geometryEntryOutputStreams(const EffectSyntax& syntax, const std::string& entry);

}  // namespace fxport::xlate
