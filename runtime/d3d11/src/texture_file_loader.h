// INTERNAL: the one texture-file loader behind D3DX11's and D3DX10's CreateShaderResourceViewFromFile
// / CreateTextureFromFile and DirectXTK's CreateDDSTextureFromFile / CreateWICTextureFromFile.
#pragma once

#include <cstddef>
#include <string>

#include "d3d11_impl.h"

namespace fxport::d3d11 {

// Which files a caller takes and how a file that is not a DDS gets its levels: D3DX reads both and
// makes an image's full mip chain; DirectXTK's DDS loader reads DDS only, its WIC loader images
// only (one level, or the full chain when given a device context).
struct TextureFileRequest {
    const char* call = "";          // for messages
    bool dds = true, images = true;  // the kinds of file taken
    bool imageMipChain = true;
    std::size_t maxSize = 0;        // DirectXTK's maxsize: larger textures are refused (0: D3D11's limits)
    int* alphaMode = nullptr;       // out, when given: a DDS's alpha mode (DDS_ALPHA_MODE's values)
};

// The texture `path` holds, a shader resource of the device: a DDS keeps its stored DXGI format,
// levels, cube faces, array items or volume slices (ID3D11Texture2D or ID3D11Texture3D); an image
// (PNG, JPEG, BMP, TGA ... through stb_image) becomes R8G8B8A8_UNORM. E_INVALIDARG/E_NOTIMPL
// naming the file when it cannot be (GetLastErrorMessage says why).
HRESULT loadTextureFile(Device* device, const std::string& path, const TextureFileRequest& request, ID3D11Resource** out);

}  // namespace fxport::d3d11
