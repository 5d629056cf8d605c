#include "d3d11_test_support.h"

#include <cstring>

namespace d3d11test {

const char* const kTexelLoadShader = R"(
float4 vs(uint id : SV_VertexID) : SV_Position {
    float2 corner = float2((id << 1) & 2, id & 2);
    return float4(corner * float2(2, -2) + float2(-1, 1), 0, 1);
}
Texture2D tex : register(t0);
float4 ps(float4 p : SV_Position) : SV_Target { return tex.Load(int3(p.xy, 0)); }
)";

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

std::vector<std::array<float, 4>> drawWithTexture(Device& d, const std::string& source, ID3D11ShaderResourceView* view, UINT width, UINT height,
                                                  ID3D11SamplerState* sampler) {
    D3D11_TEXTURE2D_DESC desc{};
    desc.Width = width;
    desc.Height = height;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    desc.SampleDesc.Count = 1;
    desc.BindFlags = D3D11_BIND_RENDER_TARGET;
    ComPtr<ID3D11Texture2D> target;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, target.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3DBlob> vsCode = compile(source, "vs", "vs_5_0"), psCode = compile(source, "ps", "ps_5_0");
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    EXPECT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK);
    EXPECT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK);
    ComPtr<ID3D11RenderTargetView> rtv;
    EXPECT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    D3D11_VIEWPORT viewport{0, 0, float(width), float(height), 0, 1};
    d.context->RSSetViewports(1, &viewport);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->PSSetShaderResources(0, 1, &view);
    if (sampler) d.context->PSSetSamplers(0, 1, &sampler);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->Draw(3, 0);
    EXPECT_EQ(lastError(), "");
    return readTexels<std::array<float, 4>>(d, target.Get());
}

ComPtr<ID3D11Texture2D> drawTriangleToRgba8(Device& d, ID3DBlob* vsCode, ID3DBlob* psCode, UINT width, UINT height) {
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    EXPECT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    EXPECT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11Texture2D> target = makeTexture(d, width, height, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv;
    EXPECT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    D3D11_VIEWPORT viewport{0, 0, float(width), float(height), 0, 1};
    d.context->RSSetViewports(1, &viewport);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->Draw(3, 0);
    EXPECT_EQ(lastError(), "");
    return target;
}

ComPtr<ID3D11Texture2D> makeFormatTexture(Device& d, DXGI_FORMAT format, UINT width, UINT height, UINT bind, const void* texels, UINT rowPitch) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = width;
    desc.Height = height;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = format;
    desc.BindFlags = bind;
    D3D11_SUBRESOURCE_DATA data{texels, rowPitch, 0};
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, texels ? &data : nullptr, t.GetAddressOf()), S_OK) << lastError();
    return t;
}

ComPtr<ID3D11ShaderResourceView> viewAs(Device& d, ID3D11Texture2D* texture, DXGI_FORMAT format) {
    D3D11_SHADER_RESOURCE_VIEW_DESC desc;
    desc.Format = format;
    desc.ViewDimension = D3D11_SRV_DIMENSION_TEXTURE2D;
    desc.Texture2D.MipLevels = 1;
    ComPtr<ID3D11ShaderResourceView> view;
    EXPECT_EQ(d.device->CreateShaderResourceView(texture, &desc, view.GetAddressOf()), S_OK) << lastError();
    return view;
}

std::vector<std::uint8_t> readTexelBytes(Device& d, ID3D11Texture2D* texture, std::size_t texelBytes) {
    D3D11_TEXTURE2D_DESC desc;
    texture->GetDesc(&desc);
    desc.Usage = D3D11_USAGE_STAGING;
    desc.BindFlags = 0;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    desc.MiscFlags = 0;
    ComPtr<ID3D11Texture2D> staging;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, staging.GetAddressOf()), S_OK) << GetLastErrorMessage();
    const std::size_t row = desc.Width * texelBytes;
    std::vector<std::uint8_t> out(row * desc.Height, 0);
    if (!staging) return out;
    d.context->CopyResource(staging.Get(), texture);
    D3D11_MAPPED_SUBRESOURCE mapped;
    EXPECT_EQ(d.context->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &mapped), S_OK) << GetLastErrorMessage();
    if (!mapped.pData) return out;
    for (UINT y = 0; y < desc.Height; ++y)
        std::memcpy(&out[y * row], static_cast<const std::uint8_t*>(mapped.pData) + std::size_t(y) * mapped.RowPitch, row);
    d.context->Unmap(staging.Get(), 0);
    return out;
}

ComPtr<ID3D11Buffer> makeBuffer(Device& d, const void* data, UINT bytes, UINT bind, UINT misc, UINT stride) {
    D3D11_BUFFER_DESC desc;
    desc.ByteWidth = bytes;
    desc.BindFlags = bind;
    desc.MiscFlags = misc;
    desc.StructureByteStride = stride;
    D3D11_SUBRESOURCE_DATA init;
    init.pSysMem = data;
    ComPtr<ID3D11Buffer> b;
    EXPECT_EQ(d.device->CreateBuffer(&desc, data ? &init : nullptr, b.GetAddressOf()), S_OK) << GetLastErrorMessage();
    return b;
}

std::vector<std::uint8_t> readBufferBytes(Device& d, ID3D11Buffer* buffer) {
    D3D11_BUFFER_DESC desc;
    buffer->GetDesc(&desc);
    D3D11_BUFFER_DESC staging;
    staging.ByteWidth = desc.ByteWidth;
    staging.Usage = D3D11_USAGE_STAGING;
    staging.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    ComPtr<ID3D11Buffer> copy;
    EXPECT_EQ(d.device->CreateBuffer(&staging, nullptr, copy.GetAddressOf()), S_OK) << GetLastErrorMessage();
    std::vector<std::uint8_t> out(desc.ByteWidth, 0);
    if (!copy) return out;
    d.context->CopyResource(copy.Get(), buffer);
    D3D11_MAPPED_SUBRESOURCE mapped;
    EXPECT_EQ(d.context->Map(copy.Get(), 0, D3D11_MAP_READ, 0, &mapped), S_OK) << GetLastErrorMessage();
    if (mapped.pData) std::memcpy(out.data(), mapped.pData, out.size());
    d.context->Unmap(copy.Get(), 0);
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
