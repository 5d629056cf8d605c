// D3DX10's texture loading with D3DX10's names: D3DX10CreateShaderResourceViewFromFile, what the
// Rastertek DX10 tutorials' TextureClass calls. The file is read as fxport's Texture2D::FromFile
// reads it (PNG, JPEG, BMP, TGA ... through stb_image; DDS with its levels), as 8-bit RGBA
// (DXGI_FORMAT_R8G8B8A8_UNORM); as D3DX10 does without a D3DX10_IMAGE_LOAD_INFO, the texture gets a
// full mip chain, each level the 2x2 box average of the one above (a DDS's own levels are kept).
#pragma once

#include "fxport/d3d10/d3d10_interfaces.h"

namespace fxport::d3d10 {

struct D3DX10_IMAGE_LOAD_INFO;  // loading options: fxport takes none (pLoadInfo must be null)

// pLoadInfo and pPump must be null. Answers E_INVALIDARG naming the file when it cannot be read
// (GetLastErrorMessage says why); *pHResult, when given, gets the same result.
HRESULT D3DX10CreateShaderResourceViewFromFile(ID3D10Device* pDevice, LPCSTR pSrcFile, D3DX10_IMAGE_LOAD_INFO* pLoadInfo, void* pPump,
                                               ID3D10ShaderResourceView** ppShaderResourceView, HRESULT* pHResult);
HRESULT D3DX10CreateShaderResourceViewFromFile(ID3D10Device* pDevice, const wchar_t* pSrcFile, D3DX10_IMAGE_LOAD_INFO* pLoadInfo,
                                               void* pPump, ID3D10ShaderResourceView** ppShaderResourceView, HRESULT* pHResult);

}  // namespace fxport::d3d10
