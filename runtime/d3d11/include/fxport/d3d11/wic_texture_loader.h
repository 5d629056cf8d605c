// DirectXTK's WICTextureLoader with its names: CreateWICTextureFromFile. The image (PNG, JPEG, BMP,
// TGA, GIF ... read by stb_image, as XNA's Texture2D::FromFile reads them) becomes an
// R8G8B8A8_UNORM Texture2D: one level, or, given a device context, the full mip chain (DirectXTK
// has the context generate it; fxport averages 2x2 texels). Wide paths as DirectXTK's, narrow
// (UTF-8) ones as an fxport addition.
// Differs from DirectXTK: always R8G8B8A8_UNORM (WIC keeps 16-bit, grey and float pixel formats);
// maxsize refuses a larger image (E_NOTIMPL) rather than resizing it; no WIC_LOADER_FLAGS; a DDS
// file is refused (CreateDDSTextureFromFile loads those).
#pragma once

#include <cstddef>

#include "fxport/d3d11/d3d11_interfaces.h"

namespace fxport::d3d11 {

// texture and textureView may each be null, not both; what is given gets a reference. E_INVALIDARG
// naming the file when it cannot be read (GetLastErrorMessage says why).
HRESULT CreateWICTextureFromFile(ID3D11Device* d3dDevice, const wchar_t* szFileName, ID3D11Resource** texture,
                                 ID3D11ShaderResourceView** textureView, std::size_t maxsize = 0);
HRESULT CreateWICTextureFromFile(ID3D11Device* d3dDevice, ID3D11DeviceContext* d3dContext, const wchar_t* szFileName, ID3D11Resource** texture,
                                 ID3D11ShaderResourceView** textureView, std::size_t maxsize = 0);
HRESULT CreateWICTextureFromFile(ID3D11Device* d3dDevice, const char* fileName, ID3D11Resource** texture, ID3D11ShaderResourceView** textureView,
                                 std::size_t maxsize = 0);
HRESULT CreateWICTextureFromFile(ID3D11Device* d3dDevice, ID3D11DeviceContext* d3dContext, const char* fileName, ID3D11Resource** texture,
                                 ID3D11ShaderResourceView** textureView, std::size_t maxsize = 0);

}  // namespace fxport::d3d11
