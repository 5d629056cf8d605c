// DirectXTK's CreateDDSTextureFromFile and CreateWICTextureFromFile (fxport/d3d11/
// dds_texture_loader.h, wic_texture_loader.h) over the one texture-file loader.
#include "d3d11_impl.h"
#include "fxport/d3d11/dds_texture_loader.h"
#include "fxport/d3d11/wic_texture_loader.h"
#include "texture_file_loader.h"

namespace fxport::d3d11 {

namespace {

// DirectXTK's checks (a device, a file name, somewhere to put the result), the loader, then the
// texture and/or its whole-texture view handed out.
HRESULT create(const TextureFileRequest& request, ID3D11Device* device11, const char* path, ID3D11Resource** texture,
               ID3D11ShaderResourceView** view) {
    const std::string call = request.call;
    if (texture) *texture = nullptr;
    if (view) *view = nullptr;
    auto* device = dynamic_cast<Device*>(device11);
    if (!device) return fail(E_INVALIDARG, call + ": d3dDevice is null or not fxport's");
    if (!path) return fail(E_INVALIDARG, call + ": the file name is null");
    if (!texture && !view) return fail(E_INVALIDARG, call + ": texture and textureView are both null");
    ComPtr<ID3D11Resource> loaded;
    if (HRESULT hr = loadTextureFile(device, path, request, loaded.GetAddressOf()); FAILED(hr)) return hr;
    if (view)
        if (HRESULT hr = device->CreateShaderResourceView(loaded.Get(), nullptr, view); FAILED(hr)) return hr;
    if (texture) *texture = loaded.Detach();
    return succeed();
}

HRESULT createDds(ID3D11Device* device, const char* path, ID3D11Resource** texture, ID3D11ShaderResourceView** view, std::size_t maxsize,
                  DDS_ALPHA_MODE* alphaMode) {
    TextureFileRequest request;
    request.call = "CreateDDSTextureFromFile";
    request.images = false;
    request.maxSize = maxsize;
    int mode = DDS_ALPHA_MODE_UNKNOWN;
    request.alphaMode = &mode;  // the DX10 header's, or premultiplied for DXT2/DXT4, as the loader reads it
    const HRESULT hr = create(request, device, path, texture, view);
    if (alphaMode) *alphaMode = SUCCEEDED(hr) ? DDS_ALPHA_MODE(mode) : DDS_ALPHA_MODE_UNKNOWN;
    return hr;
}

HRESULT createWic(ID3D11Device* device, bool withContext, const char* path, ID3D11Resource** texture, ID3D11ShaderResourceView** view,
                  std::size_t maxsize) {
    TextureFileRequest request;
    request.call = "CreateWICTextureFromFile";
    request.dds = false;
    request.imageMipChain = withContext;  // DirectXTK generates mips only when it has a context to do it with
    request.maxSize = maxsize;
    return create(request, device, path, texture, view);
}

}  // namespace

HRESULT CreateDDSTextureFromFile(ID3D11Device* d3dDevice, const char* fileName, ID3D11Resource** texture, ID3D11ShaderResourceView** textureView,
                                 std::size_t maxsize, DDS_ALPHA_MODE* alphaMode) {
    return createDds(d3dDevice, fileName, texture, textureView, maxsize, alphaMode);
}

HRESULT CreateDDSTextureFromFile(ID3D11Device* d3dDevice, ID3D11DeviceContext*, const char* fileName, ID3D11Resource** texture,
                                 ID3D11ShaderResourceView** textureView, std::size_t maxsize, DDS_ALPHA_MODE* alphaMode) {
    return createDds(d3dDevice, fileName, texture, textureView, maxsize, alphaMode);
}

HRESULT CreateDDSTextureFromFile(ID3D11Device* d3dDevice, const wchar_t* szFileName, ID3D11Resource** texture,
                                 ID3D11ShaderResourceView** textureView, std::size_t maxsize, DDS_ALPHA_MODE* alphaMode) {
    const std::string path = narrowPath(szFileName);
    return createDds(d3dDevice, szFileName ? path.c_str() : nullptr, texture, textureView, maxsize, alphaMode);
}

HRESULT CreateDDSTextureFromFile(ID3D11Device* d3dDevice, ID3D11DeviceContext*, const wchar_t* szFileName, ID3D11Resource** texture,
                                 ID3D11ShaderResourceView** textureView, std::size_t maxsize, DDS_ALPHA_MODE* alphaMode) {
    const std::string path = narrowPath(szFileName);
    return createDds(d3dDevice, szFileName ? path.c_str() : nullptr, texture, textureView, maxsize, alphaMode);
}

HRESULT CreateWICTextureFromFile(ID3D11Device* d3dDevice, const char* fileName, ID3D11Resource** texture, ID3D11ShaderResourceView** textureView,
                                 std::size_t maxsize) {
    return createWic(d3dDevice, false, fileName, texture, textureView, maxsize);
}

HRESULT CreateWICTextureFromFile(ID3D11Device* d3dDevice, ID3D11DeviceContext* d3dContext, const char* fileName, ID3D11Resource** texture,
                                 ID3D11ShaderResourceView** textureView, std::size_t maxsize) {
    return createWic(d3dDevice, d3dContext != nullptr, fileName, texture, textureView, maxsize);
}

HRESULT CreateWICTextureFromFile(ID3D11Device* d3dDevice, const wchar_t* szFileName, ID3D11Resource** texture,
                                 ID3D11ShaderResourceView** textureView, std::size_t maxsize) {
    const std::string path = narrowPath(szFileName);
    return createWic(d3dDevice, false, szFileName ? path.c_str() : nullptr, texture, textureView, maxsize);
}

HRESULT CreateWICTextureFromFile(ID3D11Device* d3dDevice, ID3D11DeviceContext* d3dContext, const wchar_t* szFileName, ID3D11Resource** texture,
                                 ID3D11ShaderResourceView** textureView, std::size_t maxsize) {
    const std::string path = narrowPath(szFileName);
    return createWic(d3dDevice, d3dContext != nullptr, szFileName ? path.c_str() : nullptr, texture, textureView, maxsize);
}

}  // namespace fxport::d3d11
