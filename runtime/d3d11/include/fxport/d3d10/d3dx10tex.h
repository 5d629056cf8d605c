// D3DX10's texture loading with D3DX10's names: D3DX10CreateShaderResourceViewFromFile, what the
// Rastertek DX10 tutorials' TextureClass calls. The same loader as D3DX11's (fxport/d3d11/
// d3dx11tex.h says what it does): a DDS keeps its stored DXGI format, levels, cube faces and volume
// slices; any other image (PNG, JPEG, BMP, TGA ... through stb_image) becomes R8G8B8A8_UNORM with a
// full mip chain, each level the 2x2 box average of the one above, as D3DX10 does without a
// D3DX10_IMAGE_LOAD_INFO.
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
