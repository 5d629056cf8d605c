// fxport addition (not in the seed): a texture's texels read back the D3D10 way, for fxdemo's
// images and --check: a STAGING copy (CopyResource) mapped for reading. D3D10 maps a texture on
// the texture itself; fxport/d3d10.h leaves ID3D10Texture2D::Map out, so the map goes through the
// D3D11 context underneath (ID3D10Device::GetD3D11Context()).
#pragma once

#include <vector>

#include "fxport/d3d10.h"

namespace Rastertek50 {

// The texels of mip 0, rows packed (width * bytesPerTexel each), top row first; empty (with the
// reason on stderr) when the copy cannot be made or mapped.
std::vector<unsigned char> ReadTexture(fxport::d3d10::ID3D10Device* device, fxport::d3d10::ID3D10Texture2D* texture,
				       unsigned int bytesPerTexel);

}  // namespace Rastertek50
