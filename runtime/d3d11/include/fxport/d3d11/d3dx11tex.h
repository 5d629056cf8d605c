// D3DX11's texture loading with D3DX11's names: D3DX11CreateShaderResourceViewFromFile (what the
// Rastertek DX11 tutorials' TextureClass and the DirectX SDK samples call) and
// D3DX11CreateTextureFromFile. A DDS file keeps what it stores: its DXGI format (BC1-BC7 as blocks,
// float and 16-bit formats as they are), its mip levels, a cube map (TEXTURECUBE view), a texture
// array, a volume (ID3D11Texture3D), a 1D texture or array (ID3D11Texture1D); a DDS whose format or partial mip chain fxport cannot hold
// natively but whose texels decode to RGBA8 (B8G8R8X8, 24-bit RGB ...) is loaded decoded as
// R8G8B8A8_UNORM. Any other image (PNG, JPEG, BMP, TGA ... through stb_image, as XNA's
// Texture2D::FromFile reads them) becomes R8G8B8A8_UNORM with a full mip chain, each level the 2x2
// box average of the one above, as D3DX does without a D3DX11_IMAGE_LOAD_INFO.
#pragma once

#include "fxport/d3d11/d3d11_interfaces.h"

namespace fxport::d3d11 {

struct D3DX11_IMAGE_LOAD_INFO;  // loading options: fxport takes none (pLoadInfo must be null)
struct ID3DX11ThreadPump;       // asynchronous loading: fxport loads at once (pPump must be null)

// pLoadInfo and pPump must be null. Answers E_INVALIDARG naming the file when it cannot be read or
// is malformed, E_NOTIMPL when it holds what fxport lacks (GetLastErrorMessage says why);
// *pHResult, when given, gets the same result.
HRESULT D3DX11CreateShaderResourceViewFromFileA(ID3D11Device* pDevice, LPCSTR pSrcFile, D3DX11_IMAGE_LOAD_INFO* pLoadInfo, ID3DX11ThreadPump* pPump,
                                                ID3D11ShaderResourceView** ppShaderResourceView, HRESULT* pHResult);
HRESULT D3DX11CreateShaderResourceViewFromFileW(ID3D11Device* pDevice, const wchar_t* pSrcFile, D3DX11_IMAGE_LOAD_INFO* pLoadInfo,
                                                ID3DX11ThreadPump* pPump, ID3D11ShaderResourceView** ppShaderResourceView, HRESULT* pHResult);
HRESULT D3DX11CreateTextureFromFileA(ID3D11Device* pDevice, LPCSTR pSrcFile, D3DX11_IMAGE_LOAD_INFO* pLoadInfo, ID3DX11ThreadPump* pPump,
                                     ID3D11Resource** ppTexture, HRESULT* pHResult);
HRESULT D3DX11CreateTextureFromFileW(ID3D11Device* pDevice, const wchar_t* pSrcFile, D3DX11_IMAGE_LOAD_INFO* pLoadInfo, ID3DX11ThreadPump* pPump,
                                     ID3D11Resource** ppTexture, HRESULT* pHResult);

// The unsuffixed names, as D3DX11's header maps them (either string type).
inline HRESULT D3DX11CreateShaderResourceViewFromFile(ID3D11Device* pDevice, LPCSTR pSrcFile, D3DX11_IMAGE_LOAD_INFO* pLoadInfo,
                                                      ID3DX11ThreadPump* pPump, ID3D11ShaderResourceView** ppShaderResourceView, HRESULT* pHResult) {
    return D3DX11CreateShaderResourceViewFromFileA(pDevice, pSrcFile, pLoadInfo, pPump, ppShaderResourceView, pHResult);
}
inline HRESULT D3DX11CreateShaderResourceViewFromFile(ID3D11Device* pDevice, const wchar_t* pSrcFile, D3DX11_IMAGE_LOAD_INFO* pLoadInfo,
                                                      ID3DX11ThreadPump* pPump, ID3D11ShaderResourceView** ppShaderResourceView, HRESULT* pHResult) {
    return D3DX11CreateShaderResourceViewFromFileW(pDevice, pSrcFile, pLoadInfo, pPump, ppShaderResourceView, pHResult);
}
inline HRESULT D3DX11CreateTextureFromFile(ID3D11Device* pDevice, LPCSTR pSrcFile, D3DX11_IMAGE_LOAD_INFO* pLoadInfo, ID3DX11ThreadPump* pPump,
                                           ID3D11Resource** ppTexture, HRESULT* pHResult) {
    return D3DX11CreateTextureFromFileA(pDevice, pSrcFile, pLoadInfo, pPump, ppTexture, pHResult);
}
inline HRESULT D3DX11CreateTextureFromFile(ID3D11Device* pDevice, const wchar_t* pSrcFile, D3DX11_IMAGE_LOAD_INFO* pLoadInfo, ID3DX11ThreadPump* pPump,
                                           ID3D11Resource** ppTexture, HRESULT* pHResult) {
    return D3DX11CreateTextureFromFileW(pDevice, pSrcFile, pLoadInfo, pPump, ppTexture, pHResult);
}

}  // namespace fxport::d3d11
