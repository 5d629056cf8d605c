#include "d3d11_test_support.h"

#include <cstring>

namespace d3d11test {

Device::Device() {
    HRESULT hr = D3D11CreateDevice(nullptr, D3D_DRIVER_TYPE_HARDWARE, nullptr, 0, nullptr, 0, D3D11_SDK_VERSION,
                                   device.GetAddressOf(), nullptr, context.GetAddressOf());
    if (FAILED(hr)) ADD_FAILURE() << "D3D11CreateDevice: " << GetLastErrorMessage();
}

ComPtr<ID3DBlob> compile(const std::string& source, const char* entry, const char* target, const char* name) {
    ComPtr<ID3DBlob> code, errors;
    HRESULT hr = D3DCompile(source.data(), source.size(), name, nullptr, nullptr, entry, target, 0, 0, code.GetAddressOf(),
                            errors.GetAddressOf());
    if (FAILED(hr))
        ADD_FAILURE() << "D3DCompile(" << (entry ? entry : "(effect)") << ", " << target << "): "
                      << (errors ? std::string(static_cast<const char*>(errors->GetBufferPointer()), errors->GetBufferSize())
                                 : std::string(GetLastErrorMessage()));
    return code;
}

std::vector<std::array<std::uint8_t, 4>> readPixels(Device& d, ID3D11Texture2D* texture) {
    D3D11_TEXTURE2D_DESC desc;
    texture->GetDesc(&desc);
    desc.Usage = D3D11_USAGE_STAGING;
    desc.BindFlags = 0;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    desc.MiscFlags = 0;
    ComPtr<ID3D11Texture2D> staging;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, staging.GetAddressOf()), S_OK) << GetLastErrorMessage();
    std::vector<std::array<std::uint8_t, 4>> out(std::size_t(desc.Width) * desc.Height);
    if (!staging) return out;
    d.context->CopyResource(staging.Get(), texture);
    D3D11_MAPPED_SUBRESOURCE mapped;
    EXPECT_EQ(d.context->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &mapped), S_OK) << GetLastErrorMessage();
    for (UINT y = 0; y < desc.Height; ++y)
        std::memcpy(&out[std::size_t(y) * desc.Width], static_cast<const std::uint8_t*>(mapped.pData) + std::size_t(y) * mapped.RowPitch,
                    std::size_t(desc.Width) * 4);
    d.context->Unmap(staging.Get(), 0);
    return out;
}

ComPtr<ID3D11Texture2D> makeTexture(Device& d, UINT width, UINT height, UINT bind, const std::vector<std::uint32_t>* texels) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = width;
    desc.Height = height;
    desc.MipLevels = 1;
    desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    desc.BindFlags = bind;
    D3D11_SUBRESOURCE_DATA data;
    if (texels) {
        data.pSysMem = texels->data();
        data.SysMemPitch = width * 4;
    }
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, texels ? &data : nullptr, t.GetAddressOf()), S_OK) << GetLastErrorMessage();
    return t;
}

std::string lastError() { return GetLastErrorMessage(); }

}  // namespace d3d11test
