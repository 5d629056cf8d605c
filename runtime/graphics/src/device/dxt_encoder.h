// BC1/BC2/BC3 (XNA's Dxt1/Dxt3/Dxt5) encoding of 8-bit RGBA levels, for TextureProcessor's
// DxtCompressed output and for completing a stored .dds mip chain kept compressed. The colour
// endpoints come from stb_dxt (Debian's libstb); BC1's transparent texels (alpha < 128) use the
// block's three-colour mode (index 3 decodes to transparent black), which stb_dxt does not write.
#pragma once

#include <cstdint>
#include <vector>

#include "fxport/graphics/surface_format.h"
#include "fxport/math.h"

namespace fxport::detail {

// `texels` is width x height, top row first; any size (edge blocks repeat the last row/column).
// `format` is Dxt1, Dxt3 or Dxt5; the result is regionBytes(format, width, height) bytes.
std::vector<std::uint8_t> encodeDxt(SurfaceFormat format, const std::vector<Color>& texels, int width, int height);

}  // namespace fxport::detail
