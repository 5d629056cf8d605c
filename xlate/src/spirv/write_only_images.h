// Typed UAVs a shader only writes take the format of the texture bound to them, as on D3D. D3D
// converts a typed UAV store to the view's format (`RWTexture2D<float4>` into an R8G8B8A8_UNORM
// texture, `RWTexture2D<uint4>` into an R32_UINT one, the extra components dropped); GL converts
// only to the image's own format, and glslang gives each image the format of its HLSL element type
// (rgba32f, rgba32ui), which an rgba8 or r32ui texture does not match. An image type no
// instruction reads (no OpImageRead, no OpImageTexelPointer for atomics) loses its format, so the
// GLSL declares a `writeonly` image without a format qualifier (GLSL 4.20+), the reflection gives
// no format, and the runtime binds the texture with its own. Images that are read keep theirs
// (D3D11 reads typed UAVs only of single-component 32-bit formats, which their types name).
#pragma once

#include "spirv/parsed_spirv.h"

namespace fxport::xlate {

// A pass of parsed_spirv.h; false (unchanged) when no storage image type is only written.
bool writeOnlyImagesWithoutFormat(ParsedSpirv& m);

}  // namespace fxport::xlate
