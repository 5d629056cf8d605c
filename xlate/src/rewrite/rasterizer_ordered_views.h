// Rasterizer-ordered views (SM 5.1 / D3D11.3 `RasterizerOrderedTexture2D<T>`, `...Buffer`,
// `...StructuredBuffer`, `...ByteAddressBuffer`, `...Texture1D/1DArray/2DArray/3D`): UAVs whose
// accesses from overlapping pixels happen in primitive order. glslang knows no such type; GL has
// the ordering in ARB_fragment_shader_interlock (not core 4.5). Each is spelled as its RW twin
// (same declaration, same operations) on the preprocessed text, before the parser, so every
// check and rewrite sees a UAV, and its name is kept: a pixel shader that still reads or writes
// one after dead-code removal runs its body as one critical section in primitive order
// (spirv/pixel_interlock.h), which the GLSL asks of the driver through the extension.
#pragma once

#include <string>
#include <vector>

namespace fxport::xlate {

// `preprocessed` with each RasterizerOrdered* type spelled RW*; the names of the variables
// declared with them are appended to `names`. Lines stay.
std::string rasterizerOrderedViewsAsUavs(const std::string& preprocessed, std::vector<std::string>& names);

}  // namespace fxport::xlate
