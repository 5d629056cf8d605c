// Entry attributes written in another case (`[MaxVertexCount(12)]`, `[Domain("tri")]`): glslang and
// fxport's own stage checks know only fxc's lower-case names. fxc takes some in any case: Intel's
// DynamicResolutionRendering and AOIT compile ZoomBox.hlsl's `[MaxVertexCount(12)]` geometry
// shaders at run time with D3DX11CompileFromFile and use the result. `numthreads` keeps its case:
// vkd3d's numthreads test pins `[NumThreads(1, 1, 1)]` as refused by fxc (SM < 6). The other names
// of the geometry, hull, domain and pixel entries are lower-cased where they start an attribute
// (`[` name) outside function bodies. Runs on the preprocessed text before the parser; the words
// keep their length, so every offset and line stays.
#pragma once

#include <string>

namespace fxport::xlate {

std::string entryAttributeNamesLowerCased(const std::string& preprocessed);

}  // namespace fxport::xlate
