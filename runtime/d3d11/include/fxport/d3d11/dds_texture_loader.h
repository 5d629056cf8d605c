// DirectXTK's DDSTextureLoader with its names: CreateDDSTextureFromFile. The file keeps what it
// stores, as D3DX11CreateTextureFromFile loads a DDS (fxport/d3d11/d3dx11tex.h says what that is);
// wide paths as DirectXTK's, narrow (UTF-8) ones as an fxport addition.
// Differs from DirectXTK: a device context (given for automatic mip generation) is accepted and not
// used (a DDS keeps its stored levels); maxsize refuses a larger texture (E_NOTIMPL) rather than
// dropping its top levels; no DDS_LOADER_FLAGS or CreateDDSTextureFromMemory.
#pragma once

#include <cstddef>

#include "fxport/d3d11/d3d11_interfaces.h"

namespace fxport::d3d11 {

enum DDS_ALPHA_MODE : unsigned {
    DDS_ALPHA_MODE_UNKNOWN = 0,
    DDS_ALPHA_MODE_STRAIGHT = 1,
    DDS_ALPHA_MODE_PREMULTIPLIED = 2,  // DXT2, DXT4, or a DX10 header that says so
    DDS_ALPHA_MODE_OPAQUE = 3,
    DDS_ALPHA_MODE_CUSTOM = 4,
};

// texture and textureView may each be null, not both; what is given gets a reference. E_INVALIDARG
// naming the file when it is not a readable DDS file, E_NOTIMPL when it holds what fxport lacks
// (GetLastErrorMessage says why).
HRESULT CreateDDSTextureFromFile(ID3D11Device* d3dDevice, const wchar_t* szFileName, ID3D11Resource** texture,
                                 ID3D11ShaderResourceView** textureView, std::size_t maxsize = 0, DDS_ALPHA_MODE* alphaMode = nullptr);
HRESULT CreateDDSTextureFromFile(ID3D11Device* d3dDevice, ID3D11DeviceContext* d3dContext, const wchar_t* szFileName, ID3D11Resource** texture,
                                 ID3D11ShaderResourceView** textureView, std::size_t maxsize = 0, DDS_ALPHA_MODE* alphaMode = nullptr);
HRESULT CreateDDSTextureFromFile(ID3D11Device* d3dDevice, const char* fileName, ID3D11Resource** texture, ID3D11ShaderResourceView** textureView,
                                 std::size_t maxsize = 0, DDS_ALPHA_MODE* alphaMode = nullptr);
HRESULT CreateDDSTextureFromFile(ID3D11Device* d3dDevice, ID3D11DeviceContext* d3dContext, const char* fileName, ID3D11Resource** texture,
                                 ID3D11ShaderResourceView** textureView, std::size_t maxsize = 0, DDS_ALPHA_MODE* alphaMode = nullptr);

}  // namespace fxport::d3d11
