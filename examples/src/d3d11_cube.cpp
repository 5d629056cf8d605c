// d3d11_cube: the DirectX SDK's Tutorial07 (a textured cube, three constant buffers, a sampler, a
// depth buffer) written as a D3D11 program writes it, with a directional light, built against the
// installed fxport (fxport::d3d11 only). Departures from the tutorial are marked `// fxport:`.
//   d3d11_cube [--size WxH] [--check]
// --check compares the read-back frame with a CPU ray cast of the same cube (d3d11_cube_check.cpp).
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "d3d11_cube_check.h"
#include "fxport/d3d11.h"

using namespace fxport::d3d11;
using cube::Matrix4;

namespace {

struct SimpleVertex {
    float Pos[3];
    float Norm[3];
    float Tex[2];
};

struct CBNeverChanges {
    Matrix4 mView;
};
struct CBChangeOnResize {
    Matrix4 mProjection;
};
struct CBChangesEveryFrame {
    Matrix4 mWorld;
    float vMeshColor[4];
    float vLightDir[4];
    float vAmbient[4];
};

ComPtr<ID3D11Device> g_pd3dDevice;
ComPtr<ID3D11DeviceContext> g_pImmediateContext;
ComPtr<ID3D11Texture2D> g_pRenderTarget;  // fxport: headless, no swap chain: the frame is a texture
ComPtr<ID3D11RenderTargetView> g_pRenderTargetView;
ComPtr<ID3D11Texture2D> g_pDepthStencil;
ComPtr<ID3D11DepthStencilView> g_pDepthStencilView;
ComPtr<ID3D11VertexShader> g_pVertexShader;
ComPtr<ID3D11PixelShader> g_pPixelShader;
ComPtr<ID3D11InputLayout> g_pVertexLayout;
ComPtr<ID3D11Buffer> g_pVertexBuffer;
ComPtr<ID3D11Buffer> g_pIndexBuffer;
ComPtr<ID3D11Buffer> g_pCBNeverChanges;
ComPtr<ID3D11Buffer> g_pCBChangeOnResize;
ComPtr<ID3D11Buffer> g_pCBChangesEveryFrame;
ComPtr<ID3D11ShaderResourceView> g_pTextureRV;
ComPtr<ID3D11SamplerState> g_pSamplerLinear;
Matrix4 g_World, g_View, g_Projection;
const float g_vMeshColor[4] = {0.9f, 0.8f, 1.0f, 1.0f};

bool Failed(HRESULT hr, const char* what) {
    if (SUCCEEDED(hr)) return false;
    std::fprintf(stderr, "d3d11_cube: %s failed: %s\n", what, GetLastErrorMessage());
    return true;
}

HRESULT CompileShaderFromFile(const char* szFileName, const char* szEntryPoint, const char* szShaderModel, ID3DBlob** ppBlobOut) {
    ComPtr<ID3DBlob> pErrorBlob;
    HRESULT hr = D3DCompileFromFile(szFileName, nullptr, D3D_COMPILE_STANDARD_FILE_INCLUDE, szEntryPoint, szShaderModel,
                                    D3DCOMPILE_ENABLE_STRICTNESS, 0, ppBlobOut, pErrorBlob.GetAddressOf());
    if (FAILED(hr) && pErrorBlob) std::fprintf(stderr, "%s\n", static_cast<const char*>(pErrorBlob->GetBufferPointer()));
    return hr;
}

HRESULT InitDevice(UINT width, UINT height, const std::string& shaderPath) {
    HRESULT hr = D3D11CreateDevice(nullptr, D3D_DRIVER_TYPE_HARDWARE, nullptr, 0, nullptr, 0, D3D11_SDK_VERSION,
                                   g_pd3dDevice.GetAddressOf(), nullptr, g_pImmediateContext.GetAddressOf());
    if (Failed(hr, "D3D11CreateDevice")) return hr;

    // fxport: the back buffer is a render-target texture read back at the end.
    D3D11_TEXTURE2D_DESC descTarget = {};
    descTarget.Width = width;
    descTarget.Height = height;
    descTarget.MipLevels = 1;
    descTarget.ArraySize = 1;
    descTarget.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    descTarget.SampleDesc.Count = 1;
    descTarget.Usage = D3D11_USAGE_DEFAULT;
    descTarget.BindFlags = D3D11_BIND_RENDER_TARGET;
    hr = g_pd3dDevice->CreateTexture2D(&descTarget, nullptr, g_pRenderTarget.GetAddressOf());
    if (Failed(hr, "CreateTexture2D (target)")) return hr;
    hr = g_pd3dDevice->CreateRenderTargetView(g_pRenderTarget.Get(), nullptr, g_pRenderTargetView.GetAddressOf());
    if (Failed(hr, "CreateRenderTargetView")) return hr;

    D3D11_TEXTURE2D_DESC descDepth = {};
    descDepth.Width = width;
    descDepth.Height = height;
    descDepth.MipLevels = 1;
    descDepth.ArraySize = 1;
    descDepth.Format = DXGI_FORMAT_D24_UNORM_S8_UINT;
    descDepth.SampleDesc.Count = 1;
    descDepth.SampleDesc.Quality = 0;
    descDepth.Usage = D3D11_USAGE_DEFAULT;
    descDepth.BindFlags = D3D11_BIND_DEPTH_STENCIL;
    descDepth.CPUAccessFlags = 0;
    descDepth.MiscFlags = 0;
    hr = g_pd3dDevice->CreateTexture2D(&descDepth, nullptr, g_pDepthStencil.GetAddressOf());
    if (Failed(hr, "CreateTexture2D (depth)")) return hr;
    D3D11_DEPTH_STENCIL_VIEW_DESC descDSV = {};
    descDSV.Format = descDepth.Format;
    descDSV.ViewDimension = D3D11_DSV_DIMENSION_TEXTURE2D;
    descDSV.Texture2D.MipSlice = 0;
    hr = g_pd3dDevice->CreateDepthStencilView(g_pDepthStencil.Get(), &descDSV, g_pDepthStencilView.GetAddressOf());
    if (Failed(hr, "CreateDepthStencilView")) return hr;
    g_pImmediateContext->OMSetRenderTargets(1, g_pRenderTargetView.GetAddressOfConst(), g_pDepthStencilView.Get());

    D3D11_VIEWPORT vp;
    vp.Width = FLOAT(width);
    vp.Height = FLOAT(height);
    vp.MinDepth = 0.0f;
    vp.MaxDepth = 1.0f;
    vp.TopLeftX = 0;
    vp.TopLeftY = 0;
    g_pImmediateContext->RSSetViewports(1, &vp);

    ComPtr<ID3DBlob> pVSBlob;
    hr = CompileShaderFromFile(shaderPath.c_str(), "VS", "vs_4_0", pVSBlob.GetAddressOf());
    if (Failed(hr, "D3DCompileFromFile (VS)")) return hr;
    hr = g_pd3dDevice->CreateVertexShader(pVSBlob->GetBufferPointer(), pVSBlob->GetBufferSize(), nullptr, g_pVertexShader.GetAddressOf());
    if (Failed(hr, "CreateVertexShader")) return hr;

    D3D11_INPUT_ELEMENT_DESC layout[] = {
        {"POSITION", 0, DXGI_FORMAT_R32G32B32_FLOAT, 0, 0, D3D11_INPUT_PER_VERTEX_DATA, 0},
        {"NORMAL", 0, DXGI_FORMAT_R32G32B32_FLOAT, 0, 12, D3D11_INPUT_PER_VERTEX_DATA, 0},
        {"TEXCOORD", 0, DXGI_FORMAT_R32G32_FLOAT, 0, 24, D3D11_INPUT_PER_VERTEX_DATA, 0},
    };
    UINT numElements = sizeof(layout) / sizeof(layout[0]);
    hr = g_pd3dDevice->CreateInputLayout(layout, numElements, pVSBlob->GetBufferPointer(), pVSBlob->GetBufferSize(),
                                         g_pVertexLayout.GetAddressOf());
    if (Failed(hr, "CreateInputLayout")) return hr;
    g_pImmediateContext->IASetInputLayout(g_pVertexLayout.Get());

    ComPtr<ID3DBlob> pPSBlob;
    hr = CompileShaderFromFile(shaderPath.c_str(), "PS", "ps_4_0", pPSBlob.GetAddressOf());
    if (Failed(hr, "D3DCompileFromFile (PS)")) return hr;
    hr = g_pd3dDevice->CreatePixelShader(pPSBlob->GetBufferPointer(), pPSBlob->GetBufferSize(), nullptr, g_pPixelShader.GetAddressOf());
    if (Failed(hr, "CreatePixelShader")) return hr;

    // The cube: 24 vertices, 4 per face, so each face has its own normal and texture coordinates.
    std::vector<SimpleVertex> vertices;
    std::vector<unsigned short> indices;
    for (const cube::Face& f : cube::faces()) {
        const unsigned short base = static_cast<unsigned short>(vertices.size());
        const float corners[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};  // (s, t): TL, TR, BR, BL seen from outside
        for (const auto& c : corners) {
            const cube::Vec3 p = f.pointAt(c[0], c[1]);
            vertices.push_back({{float(p.x), float(p.y), float(p.z)}, {float(f.n.x), float(f.n.y), float(f.n.z)}, {c[0], c[1]}});
        }
        for (unsigned short i : {0, 1, 2, 0, 2, 3}) indices.push_back(static_cast<unsigned short>(base + i));  // clockwise from outside
    }
    D3D11_BUFFER_DESC bd = {};
    bd.Usage = D3D11_USAGE_DEFAULT;
    bd.ByteWidth = UINT(sizeof(SimpleVertex) * vertices.size());
    bd.BindFlags = D3D11_BIND_VERTEX_BUFFER;
    bd.CPUAccessFlags = 0;
    D3D11_SUBRESOURCE_DATA InitData = {};
    InitData.pSysMem = vertices.data();
    hr = g_pd3dDevice->CreateBuffer(&bd, &InitData, g_pVertexBuffer.GetAddressOf());
    if (Failed(hr, "CreateBuffer (vertices)")) return hr;
    UINT stride = sizeof(SimpleVertex);
    UINT offset = 0;
    g_pImmediateContext->IASetVertexBuffers(0, 1, g_pVertexBuffer.GetAddressOfConst(), &stride, &offset);

    bd.Usage = D3D11_USAGE_DEFAULT;
    bd.ByteWidth = UINT(sizeof(unsigned short) * indices.size());
    bd.BindFlags = D3D11_BIND_INDEX_BUFFER;
    InitData.pSysMem = indices.data();
    hr = g_pd3dDevice->CreateBuffer(&bd, &InitData, g_pIndexBuffer.GetAddressOf());
    if (Failed(hr, "CreateBuffer (indices)")) return hr;
    g_pImmediateContext->IASetIndexBuffer(g_pIndexBuffer.Get(), DXGI_FORMAT_R16_UINT, 0);
    g_pImmediateContext->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);

    bd.Usage = D3D11_USAGE_DEFAULT;
    bd.ByteWidth = sizeof(CBNeverChanges);
    bd.BindFlags = D3D11_BIND_CONSTANT_BUFFER;
    bd.CPUAccessFlags = 0;
    hr = g_pd3dDevice->CreateBuffer(&bd, nullptr, g_pCBNeverChanges.GetAddressOf());
    if (Failed(hr, "CreateBuffer (cbNeverChanges)")) return hr;
    bd.ByteWidth = sizeof(CBChangeOnResize);
    hr = g_pd3dDevice->CreateBuffer(&bd, nullptr, g_pCBChangeOnResize.GetAddressOf());
    if (Failed(hr, "CreateBuffer (cbChangeOnResize)")) return hr;
    bd.ByteWidth = sizeof(CBChangesEveryFrame);
    hr = g_pd3dDevice->CreateBuffer(&bd, nullptr, g_pCBChangesEveryFrame.GetAddressOf());
    if (Failed(hr, "CreateBuffer (cbChangesEveryFrame)")) return hr;

    // fxport: the tutorial loads seafloor.dds; this is a 4x4 checker made in memory (cube::texel).
    std::vector<std::uint32_t> texels(cube::kTextureSize * cube::kTextureSize);
    for (int y = 0; y < cube::kTextureSize; ++y)
        for (int x = 0; x < cube::kTextureSize; ++x) texels[std::size_t(y * cube::kTextureSize + x)] = cube::texel(x, y);
    D3D11_TEXTURE2D_DESC descTexture = descTarget;
    descTexture.Width = descTexture.Height = cube::kTextureSize;
    descTexture.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    D3D11_SUBRESOURCE_DATA texData = {};
    texData.pSysMem = texels.data();
    texData.SysMemPitch = cube::kTextureSize * 4;
    ComPtr<ID3D11Texture2D> texture;
    hr = g_pd3dDevice->CreateTexture2D(&descTexture, &texData, texture.GetAddressOf());
    if (Failed(hr, "CreateTexture2D (texture)")) return hr;
    hr = g_pd3dDevice->CreateShaderResourceView(texture.Get(), nullptr, g_pTextureRV.GetAddressOf());
    if (Failed(hr, "CreateShaderResourceView")) return hr;

    D3D11_SAMPLER_DESC sampDesc = {};
    sampDesc.Filter = D3D11_FILTER_MIN_MAG_MIP_POINT;  // fxport: point sampling, so the CPU check is exact
    sampDesc.AddressU = D3D11_TEXTURE_ADDRESS_WRAP;
    sampDesc.AddressV = D3D11_TEXTURE_ADDRESS_WRAP;
    sampDesc.AddressW = D3D11_TEXTURE_ADDRESS_WRAP;
    sampDesc.ComparisonFunc = D3D11_COMPARISON_NEVER;
    sampDesc.MinLOD = 0;
    sampDesc.MaxLOD = D3D11_FLOAT32_MAX;
    hr = g_pd3dDevice->CreateSamplerState(&sampDesc, g_pSamplerLinear.GetAddressOf());
    if (Failed(hr, "CreateSamplerState")) return hr;

    g_World = cube::world(0);
    g_View = cube::view();
    CBNeverChanges cbNeverChanges;
    cbNeverChanges.mView = cube::transpose(g_View);
    g_pImmediateContext->UpdateSubresource(g_pCBNeverChanges.Get(), 0, nullptr, &cbNeverChanges, 0, 0);
    g_Projection = cube::projection(double(width) / height);
    CBChangeOnResize cbChangesOnResize;
    cbChangesOnResize.mProjection = cube::transpose(g_Projection);
    g_pImmediateContext->UpdateSubresource(g_pCBChangeOnResize.Get(), 0, nullptr, &cbChangesOnResize, 0, 0);
    return S_OK;
}

void Render(double t) {
    g_World = cube::world(t);
    float ClearColor[4] = {0.0f, 0.125f, 0.3f, 1.0f};
    g_pImmediateContext->ClearRenderTargetView(g_pRenderTargetView.Get(), ClearColor);
    g_pImmediateContext->ClearDepthStencilView(g_pDepthStencilView.Get(), D3D11_CLEAR_DEPTH, 1.0f, 0);

    CBChangesEveryFrame cb;
    cb.mWorld = cube::transpose(g_World);
    std::memcpy(cb.vMeshColor, g_vMeshColor, sizeof cb.vMeshColor);
    for (int i = 0; i < 4; ++i) cb.vLightDir[i] = float(cube::kLightDirection[i]);
    for (int i = 0; i < 4; ++i) cb.vAmbient[i] = float(cube::kAmbient);
    g_pImmediateContext->UpdateSubresource(g_pCBChangesEveryFrame.Get(), 0, nullptr, &cb, 0, 0);

    g_pImmediateContext->VSSetShader(g_pVertexShader.Get(), nullptr, 0);
    ID3D11Buffer* vsBuffers[3] = {g_pCBNeverChanges.Get(), g_pCBChangeOnResize.Get(), g_pCBChangesEveryFrame.Get()};
    g_pImmediateContext->VSSetConstantBuffers(0, 3, vsBuffers);
    g_pImmediateContext->PSSetShader(g_pPixelShader.Get(), nullptr, 0);
    g_pImmediateContext->PSSetConstantBuffers(2, 1, g_pCBChangesEveryFrame.GetAddressOfConst());
    g_pImmediateContext->PSSetShaderResources(0, 1, g_pTextureRV.GetAddressOfConst());
    g_pImmediateContext->PSSetSamplers(0, 1, g_pSamplerLinear.GetAddressOfConst());
    g_pImmediateContext->DrawIndexed(36, 0, 0);
    // fxport: no Present; the frame stays in g_pRenderTarget.
}

// fxport: the frame read back as D3D code reads a texture: a staging copy, then Map(READ).
std::vector<std::uint8_t> ReadFrame(UINT width, UINT height) {
    D3D11_TEXTURE2D_DESC desc;
    g_pRenderTarget->GetDesc(&desc);
    desc.Usage = D3D11_USAGE_STAGING;
    desc.BindFlags = 0;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    ComPtr<ID3D11Texture2D> staging;
    std::vector<std::uint8_t> rgba(std::size_t(width) * height * 4);
    if (Failed(g_pd3dDevice->CreateTexture2D(&desc, nullptr, staging.GetAddressOf()), "CreateTexture2D (staging)")) return rgba;
    g_pImmediateContext->CopyResource(staging.Get(), g_pRenderTarget.Get());
    D3D11_MAPPED_SUBRESOURCE mapped;
    if (Failed(g_pImmediateContext->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &mapped), "Map")) return rgba;
    for (UINT y = 0; y < height; ++y)
        std::memcpy(&rgba[std::size_t(y) * width * 4], static_cast<const std::uint8_t*>(mapped.pData) + std::size_t(y) * mapped.RowPitch, width * 4);
    g_pImmediateContext->Unmap(staging.Get(), 0);
    return rgba;
}

void CleanupDevice() {
    if (g_pImmediateContext) g_pImmediateContext->ClearState();
    g_pSamplerLinear.Reset();
    g_pTextureRV.Reset();
    g_pCBNeverChanges.Reset();
    g_pCBChangeOnResize.Reset();
    g_pCBChangesEveryFrame.Reset();
    g_pVertexBuffer.Reset();
    g_pIndexBuffer.Reset();
    g_pVertexLayout.Reset();
    g_pVertexShader.Reset();
    g_pPixelShader.Reset();
    g_pDepthStencil.Reset();
    g_pDepthStencilView.Reset();
    g_pRenderTargetView.Reset();
    g_pRenderTarget.Reset();
    g_pImmediateContext.Reset();
    g_pd3dDevice.Reset();
}

}  // namespace

int main(int argc, char** argv) {
    UINT width = 160, height = 120;
    bool check = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--check") check = true;
        else if (a == "--size" && i + 1 < argc && std::sscanf(argv[++i], "%ux%u", &width, &height) == 2 && width > 0 && height > 0) continue;
        else {
            std::fprintf(stderr, "usage: d3d11_cube [--size WxH] [--check]\n");
            return 2;
        }
    }
    // The shader file is installed beside the program (CMakeLists.txt copies it).
    const std::string shaderPath = (std::filesystem::path(argv[0]).parent_path() / "d3d11_cube.hlsl").string();
    if (FAILED(InitDevice(width, height, shaderPath))) {
        CleanupDevice();
        return 1;
    }
    const double t = 0.6;  // seconds into the tutorial's rotation
    Render(t);
    if (*GetLastErrorMessage()) {
        std::fprintf(stderr, "d3d11_cube: the draw was refused: %s\n", GetLastErrorMessage());
        CleanupDevice();
        return 1;
    }
    const std::vector<std::uint8_t> frame = ReadFrame(width, height);
    CleanupDevice();
    std::printf("d3d11_cube: %ux%u frame rendered\n", width, height);
    if (!check) return 0;
    const cube::Check result = cube::checkFrame(frame, int(width), int(height), t, g_vMeshColor);
    std::printf("d3d11_cube check: %s\n", result.summary().c_str());
    return result.passed() ? 0 : 1;
}
