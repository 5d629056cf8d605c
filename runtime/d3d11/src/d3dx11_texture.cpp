// D3DX11CreateShaderResourceViewFromFile / D3DX11CreateTextureFromFile (fxport/d3d11/d3dx11tex.h)
// and D3DX10CreateShaderResourceViewFromFile (fxport/d3d10/d3dx10tex.h): one loader
// (texture_file_loader.h) under D3DX's spellings, with D3DX's argument checks.
#include "d3d11_impl.h"
#include "fxport/d3d10/d3dx10tex.h"
#include "fxport/d3d11/d3dx11tex.h"
#include "texture_file_loader.h"

namespace fxport::d3d11 {

namespace {

HRESULT answer(HRESULT hr, HRESULT* pHResult) {
    if (pHResult) *pHResult = hr;
    return hr;
}

// D3DX's checks, then the file through the loader (a full mip chain for images, as D3DX's defaults).
HRESULT loadResource(const char* call, ID3D11Device* device11, const char* path, const void* info, const void* pump, ID3D11Resource** pp) {
    auto* device = dynamic_cast<Device*>(device11);
    if (!device) return fail(E_INVALIDARG, std::string(call) + ": pDevice is null or not fxport's");
    if (!path) return fail(E_INVALIDARG, std::string(call) + ": pSrcFile is null");
    if (info) return fail(E_NOTIMPL, std::string(call) + ": pLoadInfo is not null: fxport loads with D3DX's defaults only");
    if (pump) return fail(E_NOTIMPL, std::string(call) + ": pPump is not null: fxport loads at once (no thread pump)");
    if (!pp) return fail(E_INVALIDARG, std::string(call) + ": the out pointer is null");
    TextureFileRequest request;
    request.call = call;
    return loadTextureFile(device, path, request, pp);
}

// The resource's whole-texture view (TEXTURE2D, TEXTURECUBE, TEXTURE2DARRAY or TEXTURE3D).
HRESULT loadView(const char* call, ID3D11Device* device, const char* path, const void* info, const void* pump, ID3D11ShaderResourceView** pp) {
    if (!pp) return fail(E_INVALIDARG, std::string(call) + ": ppShaderResourceView is null");
    *pp = nullptr;
    ComPtr<ID3D11Resource> texture;
    if (HRESULT hr = loadResource(call, device, path, info, pump, texture.GetAddressOf()); FAILED(hr)) return hr;
    return device->CreateShaderResourceView(texture.Get(), nullptr, pp);  // the view holds the texture
}

}  // namespace

HRESULT D3DX11CreateShaderResourceViewFromFileA(ID3D11Device* pDevice, LPCSTR pSrcFile, D3DX11_IMAGE_LOAD_INFO* pLoadInfo, ID3DX11ThreadPump* pPump,
                                                ID3D11ShaderResourceView** ppShaderResourceView, HRESULT* pHResult) {
    return answer(loadView("D3DX11CreateShaderResourceViewFromFile", pDevice, pSrcFile, pLoadInfo, pPump, ppShaderResourceView), pHResult);
}

HRESULT D3DX11CreateShaderResourceViewFromFileW(ID3D11Device* pDevice, const wchar_t* pSrcFile, D3DX11_IMAGE_LOAD_INFO* pLoadInfo,
                                                ID3DX11ThreadPump* pPump, ID3D11ShaderResourceView** ppShaderResourceView, HRESULT* pHResult) {
    const std::string path = narrowPath(pSrcFile);
    return answer(loadView("D3DX11CreateShaderResourceViewFromFile", pDevice, pSrcFile ? path.c_str() : nullptr, pLoadInfo, pPump, ppShaderResourceView),
                  pHResult);
}

HRESULT D3DX11CreateTextureFromFileA(ID3D11Device* pDevice, LPCSTR pSrcFile, D3DX11_IMAGE_LOAD_INFO* pLoadInfo, ID3DX11ThreadPump* pPump,
                                     ID3D11Resource** ppTexture, HRESULT* pHResult) {
    if (ppTexture) *ppTexture = nullptr;
    return answer(loadResource("D3DX11CreateTextureFromFile", pDevice, pSrcFile, pLoadInfo, pPump, ppTexture), pHResult);
}

HRESULT D3DX11CreateTextureFromFileW(ID3D11Device* pDevice, const wchar_t* pSrcFile, D3DX11_IMAGE_LOAD_INFO* pLoadInfo, ID3DX11ThreadPump* pPump,
                                     ID3D11Resource** ppTexture, HRESULT* pHResult) {
    if (ppTexture) *ppTexture = nullptr;
    const std::string path = narrowPath(pSrcFile);
    return answer(loadResource("D3DX11CreateTextureFromFile", pDevice, pSrcFile ? path.c_str() : nullptr, pLoadInfo, pPump, ppTexture), pHResult);
}

}  // namespace fxport::d3d11

namespace fxport::d3d10 {

namespace {

HRESULT loadView10(ID3D10Device* device10, const char* path, D3DX10_IMAGE_LOAD_INFO* info, void* pump, ID3D10ShaderResourceView** pp, HRESULT* pHResult) {
    const char* call = "D3DX10CreateShaderResourceViewFromFile";
    ID3D11Device* device = device10 ? device10->GetD3D11Device() : nullptr;
    HRESULT hr = device ? d3d11::loadView(call, device, path, info, pump, pp) : d3d11::fail(E_INVALIDARG, std::string(call) + ": pDevice is null or not fxport's");
    return d3d11::answer(hr, pHResult);
}

}  // namespace

HRESULT D3DX10CreateShaderResourceViewFromFile(ID3D10Device* pDevice, LPCSTR pSrcFile, D3DX10_IMAGE_LOAD_INFO* pLoadInfo, void* pPump,
                                               ID3D10ShaderResourceView** ppShaderResourceView, HRESULT* pHResult) {
    return loadView10(pDevice, pSrcFile, pLoadInfo, pPump, ppShaderResourceView, pHResult);
}

HRESULT D3DX10CreateShaderResourceViewFromFile(ID3D10Device* pDevice, const wchar_t* pSrcFile, D3DX10_IMAGE_LOAD_INFO* pLoadInfo,
                                               void* pPump, ID3D10ShaderResourceView** ppShaderResourceView, HRESULT* pHResult) {
    const std::string path = d3d11::narrowPath(pSrcFile);
    return loadView10(pDevice, pSrcFile ? path.c_str() : nullptr, pLoadInfo, pPump, ppShaderResourceView, pHResult);
}

}  // namespace fxport::d3d10
