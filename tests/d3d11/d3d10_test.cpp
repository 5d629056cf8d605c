// The D3D10 spellings (fxport/d3d10.h) as the Rastertek DX10 deferred tutorial (seed 004) uses
// them: D3D10CreateDeviceAndSwapChain, the swap chain's back buffer, D3DX10CreateEffectFromFile
// on an .fx file, GetTechniqueByName, GetPassByIndex(0)->GetDesc for the input layout,
// GetVariableByName(...)->AsMatrix()->SetMatrix / AsVector / AsShaderResource()->SetResource,
// Apply(0) and DrawIndexed into two float render targets (colour and normal) with a depth buffer;
// then a D3D10_BLEND_DESC (one blend, per-target enable and write mask) adding the colour again.
// The pixels are compared with a CPU computation of the effect's math. A broken .fx leaves the
// compiler's file:line message in ppErrors.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>

#include <gtest/gtest.h>

#include "fxport/d3d10.h"

namespace d3d10test {
namespace {

using namespace fxport::d3d10;

const char* kDeferredFx = R"(
matrix worldMatrix;
matrix viewMatrix;
matrix projectionMatrix;
float4 tint;
Texture2D shaderTexture;
SamplerState SampleTypeWrap { Filter = MIN_MAG_MIP_POINT; AddressU = Wrap; AddressV = Wrap; };

struct VertexInputType { float4 position : POSITION; float2 tex : TEXCOORD0; float3 normal : NORMAL; };
struct PixelInputType { float4 position : SV_POSITION; float2 tex : TEXCOORD0; float3 normal : NORMAL; };
struct PixelOutputType { float4 color : SV_Target0; float4 normal : SV_Target1; };

PixelInputType DeferredVertexShader(VertexInputType input)
{
    PixelInputType output;
    input.position.w = 1.0f;
    output.position = mul(input.position, worldMatrix);
    output.position = mul(output.position, viewMatrix);
    output.position = mul(output.position, projectionMatrix);
    output.tex = input.tex;
    output.normal = normalize(mul(input.normal, (float3x3)worldMatrix));
    return output;
}

PixelOutputType DeferredPixelShader(PixelInputType input) : SV_TARGET
{
    PixelOutputType output;
    output.color = shaderTexture.Sample(SampleTypeWrap, input.tex) * tint;
    output.normal = float4(input.normal, 1.0f);
    return output;
}

technique10 DeferredTechnique
{
    pass pass0
    {
        SetVertexShader(CompileShader(vs_4_0, DeferredVertexShader()));
        SetPixelShader(CompileShader(ps_4_0, DeferredPixelShader()));
        SetGeometryShader(NULL);
    }
}
)";

std::string writeFile(const std::string& name, const char* text) {
    const std::string path = ::testing::TempDir() + name;
    std::ofstream(path) << text;
    return path;
}

// RGBA floats of a texture (R32G32B32A32_FLOAT), through a staging copy on the D3D11 context
// underneath (D3D10 maps on the resource itself, which fxport does not have).
std::vector<float> readFloats(ID3D10Device* device, ID3D10Texture2D* texture) {
    D3D10_TEXTURE2D_DESC desc;
    texture->GetDesc(&desc);
    desc.Usage = D3D10_USAGE_STAGING;
    desc.BindFlags = 0;
    desc.CPUAccessFlags = D3D10_CPU_ACCESS_READ;
    ComPtr<ID3D10Texture2D> staging;
    EXPECT_EQ(device->CreateTexture2D(&desc, nullptr, staging.GetAddressOf()), S_OK) << GetLastErrorMessage();
    std::vector<float> out(std::size_t(desc.Width) * desc.Height * 4);
    if (!staging) return out;
    device->CopyResource(staging.Get(), texture);
    D3D11_MAPPED_SUBRESOURCE mapped;
    EXPECT_EQ(device->GetD3D11Context()->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &mapped), S_OK) << GetLastErrorMessage();
    for (UINT y = 0; y < desc.Height && mapped.pData; ++y)
        std::memcpy(&out[std::size_t(y) * desc.Width * 4], static_cast<const std::uint8_t*>(mapped.pData) + std::size_t(y) * mapped.RowPitch,
                    std::size_t(desc.Width) * 16);
    device->GetD3D11Context()->Unmap(staging.Get(), 0);
    return out;
}

constexpr UINT kSize = 16;

struct D3D10Test : ::testing::Test {
    ComPtr<ID3D10Device> device;
    ComPtr<IDXGISwapChain> swapChain;

    void SetUp() override {
        DXGI_SWAP_CHAIN_DESC sd;
        sd.BufferCount = 1;
        sd.BufferDesc.Width = kSize;
        sd.BufferDesc.Height = kSize;
        sd.BufferDesc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
        sd.BufferUsage = DXGI_USAGE_RENDER_TARGET_OUTPUT;
        sd.Windowed = TRUE;
        ASSERT_EQ(D3D10CreateDeviceAndSwapChain(nullptr, D3D10_DRIVER_TYPE_HARDWARE, nullptr, 0, D3D10_SDK_VERSION, &sd, swapChain.GetAddressOf(),
                                                device.GetAddressOf()),
                  S_OK)
            << GetLastErrorMessage();
    }
    ComPtr<ID3D10Texture2D> floatTarget(ComPtr<ID3D10RenderTargetView>& view, ComPtr<ID3D10ShaderResourceView>& resource) {
        D3D10_TEXTURE2D_DESC td;  // as DeferredBuffersClass::Initialize makes its targets
        td.Width = td.Height = kSize;
        td.MipLevels = 1;
        td.ArraySize = 1;
        td.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
        td.Usage = D3D10_USAGE_DEFAULT;
        td.BindFlags = D3D10_BIND_RENDER_TARGET | D3D10_BIND_SHADER_RESOURCE;
        ComPtr<ID3D10Texture2D> t;
        EXPECT_EQ(device->CreateTexture2D(&td, nullptr, t.GetAddressOf()), S_OK) << GetLastErrorMessage();
        D3D10_RENDER_TARGET_VIEW_DESC rd;
        rd.Format = td.Format;
        rd.ViewDimension = D3D10_RTV_DIMENSION_TEXTURE2D;
        EXPECT_EQ(device->CreateRenderTargetView(t.Get(), &rd, view.GetAddressOf()), S_OK) << GetLastErrorMessage();
        D3D10_SHADER_RESOURCE_VIEW_DESC sd;
        sd.Format = td.Format;
        sd.ViewDimension = D3D10_SRV_DIMENSION_TEXTURE2D;
        sd.Texture2D.MipLevels = 1;
        EXPECT_EQ(device->CreateShaderResourceView(t.Get(), &sd, resource.GetAddressOf()), S_OK) << GetLastErrorMessage();
        return t;
    }
};

// 2x2 texels.
const std::uint32_t kTexels[4] = {0xff2040c0u, 0xffc04020u, 0xff80ff10u, 0xff10e0ffu};

TEST_F(D3D10Test, DeferredEffectDrawsWhatTheCpuComputes) {
    ComPtr<ID3D10Effect> effect;
    ComPtr<ID3D10Blob> errors;
    const std::string path = writeFile("fxport_d3d10_deferred.fx", kDeferredFx);
    ASSERT_EQ(D3DX10CreateEffectFromFile(path.c_str(), nullptr, nullptr, "fx_4_0", D3D10_SHADER_ENABLE_STRICTNESS, 0, device.Get(), nullptr,
                                         nullptr, effect.GetAddressOf(), errors.GetAddressOf(), nullptr),
              S_OK)
        << GetLastErrorMessage();
    ID3D10EffectTechnique* technique = effect->GetTechniqueByName("DeferredTechnique");
    ASSERT_TRUE(technique && technique->IsValid());
    EXPECT_FALSE(effect->GetTechniqueByName("Missing")->IsValid());
    ID3D10EffectMatrixVariable* worldMatrixPtr = effect->GetVariableByName("worldMatrix")->AsMatrix();
    ID3D10EffectMatrixVariable* viewMatrixPtr = effect->GetVariableByName("viewMatrix")->AsMatrix();
    ID3D10EffectMatrixVariable* projectionMatrixPtr = effect->GetVariableByName("projectionMatrix")->AsMatrix();
    ID3D10EffectShaderResourceVariable* texturePtr = effect->GetVariableByName("shaderTexture")->AsShaderResource();
    ID3D10EffectVectorVariable* tintPtr = effect->GetVariableByName("tint")->AsVector();

    // The layout from the pass's signature, as DeferredShaderClass::InitializeShader makes it.
    D3D10_INPUT_ELEMENT_DESC polygonLayout[3] = {
        {"POSITION", 0, DXGI_FORMAT_R32G32B32_FLOAT, 0, 0, D3D10_INPUT_PER_VERTEX_DATA, 0},
        {"TEXCOORD", 0, DXGI_FORMAT_R32G32_FLOAT, 0, D3D10_APPEND_ALIGNED_ELEMENT, D3D10_INPUT_PER_VERTEX_DATA, 0},
        {"NORMAL", 0, DXGI_FORMAT_R32G32B32_FLOAT, 0, D3D10_APPEND_ALIGNED_ELEMENT, D3D10_INPUT_PER_VERTEX_DATA, 0},
    };
    D3D10_PASS_DESC passDesc;
    ASSERT_EQ(technique->GetPassByIndex(0)->GetDesc(&passDesc), S_OK) << GetLastErrorMessage();
    ComPtr<ID3D10InputLayout> layout;
    ASSERT_EQ(device->CreateInputLayout(polygonLayout, 3, passDesc.pIAInputSignature, passDesc.IAInputSignatureSize, layout.GetAddressOf()), S_OK)
        << GetLastErrorMessage();

    struct Vertex {
        float position[3], tex[2], normal[3];
    };
    const Vertex quad[4] = {{{-1, 1, 0}, {0, 0}, {0, 0, -1}}, {{1, 1, 0}, {1, 0}, {0, 0, -1}}, {{1, -1, 0}, {1, 1}, {0, 0, -1}},
                            {{-1, -1, 0}, {0, 1}, {0, 0, -1}}};
    const std::uint32_t indices32[6] = {0, 1, 2, 0, 2, 3};  // the tutorial's unsigned long is 32-bit on Windows only
    D3D10_BUFFER_DESC bd;
    bd.Usage = D3D10_USAGE_DEFAULT;
    bd.ByteWidth = sizeof quad;
    bd.BindFlags = D3D10_BIND_VERTEX_BUFFER;
    D3D10_SUBRESOURCE_DATA data;
    data.pSysMem = quad;
    ComPtr<ID3D10Buffer> vertexBuffer, indexBuffer;
    ASSERT_EQ(device->CreateBuffer(&bd, &data, vertexBuffer.GetAddressOf()), S_OK) << GetLastErrorMessage();
    bd.ByteWidth = sizeof indices32;
    bd.BindFlags = D3D10_BIND_INDEX_BUFFER;
    data.pSysMem = indices32;
    ASSERT_EQ(device->CreateBuffer(&bd, &data, indexBuffer.GetAddressOf()), S_OK) << GetLastErrorMessage();
    D3D10_TEXTURE2D_DESC td;
    td.Width = td.Height = 2;
    td.MipLevels = 1;
    td.ArraySize = 1;
    td.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    td.BindFlags = D3D10_BIND_SHADER_RESOURCE;
    data.pSysMem = kTexels;
    data.SysMemPitch = 8;
    ComPtr<ID3D10Texture2D> texture;
    ASSERT_EQ(device->CreateTexture2D(&td, &data, texture.GetAddressOf()), S_OK) << GetLastErrorMessage();
    ComPtr<ID3D10ShaderResourceView> textureView;
    ASSERT_EQ(device->CreateShaderResourceView(texture.Get(), nullptr, textureView.GetAddressOf()), S_OK) << GetLastErrorMessage();

    // The deferred buffers: two float targets and a depth buffer (DeferredBuffersClass).
    ComPtr<ID3D10RenderTargetView> colorView, normalView;
    ComPtr<ID3D10ShaderResourceView> colorResource, normalResource;
    ComPtr<ID3D10Texture2D> color = floatTarget(colorView, colorResource), normal = floatTarget(normalView, normalResource);
    D3D10_TEXTURE2D_DESC dd;
    dd.Width = dd.Height = kSize;
    dd.MipLevels = 1;
    dd.ArraySize = 1;
    dd.Format = DXGI_FORMAT_D24_UNORM_S8_UINT;
    dd.Usage = D3D10_USAGE_DEFAULT;
    dd.BindFlags = D3D10_BIND_DEPTH_STENCIL;
    ComPtr<ID3D10Texture2D> depth;
    ASSERT_EQ(device->CreateTexture2D(&dd, nullptr, depth.GetAddressOf()), S_OK) << GetLastErrorMessage();
    D3D10_DEPTH_STENCIL_VIEW_DESC dsd;
    dsd.Format = dd.Format;
    dsd.ViewDimension = D3D10_DSV_DIMENSION_TEXTURE2D;
    ComPtr<ID3D10DepthStencilView> depthView;
    ASSERT_EQ(device->CreateDepthStencilView(depth.Get(), &dsd, depthView.GetAddressOf()), S_OK) << GetLastErrorMessage();

    ID3D10RenderTargetView* targets[2] = {colorView.Get(), normalView.Get()};
    device->OMSetRenderTargets(2, targets, depthView.Get());
    D3D10_VIEWPORT viewport;
    viewport.Width = kSize;
    viewport.Height = kSize;
    device->RSSetViewports(1, &viewport);
    const float clear[4] = {0, 0, 0, 0};
    device->ClearRenderTargetView(colorView.Get(), clear);
    device->ClearRenderTargetView(normalView.Get(), clear);
    device->ClearDepthStencilView(depthView.Get(), D3D10_CLEAR_DEPTH, 1.0f, 0);

    // World: scale 0.5, move (0.25, 0.25); view: move (-0.5, 0); projection: x * 2 (row vectors).
    const float world[16] = {0.5f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 1, 0, 0.25f, 0.25f, 0, 1};
    const float view[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, -0.5f, 0, 0, 1};
    const float projection[16] = {2, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    const float tint[4] = {1.0f, 0.5f, 0.25f, 1.0f};
    ASSERT_EQ(worldMatrixPtr->SetMatrix(world), S_OK) << GetLastErrorMessage();
    ASSERT_EQ(viewMatrixPtr->SetMatrix(view), S_OK);
    ASSERT_EQ(projectionMatrixPtr->SetMatrix(projection), S_OK);
    ASSERT_EQ(tintPtr->SetFloatVector(tint), S_OK);
    ASSERT_EQ(texturePtr->SetResource(textureView.Get()), S_OK) << GetLastErrorMessage();

    const UINT stride = sizeof(Vertex), offset = 0;
    device->IASetVertexBuffers(0, 1, vertexBuffer.GetAddressOfConst(), &stride, &offset);
    device->IASetIndexBuffer(indexBuffer.Get(), DXGI_FORMAT_R32_UINT, 0);
    device->IASetPrimitiveTopology(D3D10_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    device->IASetInputLayout(layout.Get());
    D3D10_TECHNIQUE_DESC techniqueDesc;
    ASSERT_EQ(technique->GetDesc(&techniqueDesc), S_OK);
    ASSERT_EQ(techniqueDesc.Passes, 1u);
    for (UINT i = 0; i < techniqueDesc.Passes; ++i) {
        ASSERT_EQ(technique->GetPassByIndex(i)->Apply(0), S_OK) << GetLastErrorMessage();
        device->DrawIndexed(6, 0, 0);
        ASSERT_STREQ(GetLastErrorMessage(), "");
    }

    // Then the same quad again, added onto the colour target only (the normal target's write
    // mask is 0): D3D10's one blend, enabled per target.
    D3D10_BLEND_DESC blend;
    for (UINT8& mask : blend.RenderTargetWriteMask) mask = 0;  // as the tutorials' ZeroMemory leaves them: targets 1..7 not written
    blend.BlendEnable[0] = TRUE;
    blend.SrcBlend = D3D10_BLEND_ONE;
    blend.DestBlend = D3D10_BLEND_ONE;
    blend.BlendOp = D3D10_BLEND_OP_ADD;
    blend.SrcBlendAlpha = D3D10_BLEND_ONE;
    blend.DestBlendAlpha = D3D10_BLEND_ONE;
    blend.BlendOpAlpha = D3D10_BLEND_OP_ADD;
    blend.RenderTargetWriteMask[0] = D3D10_COLOR_WRITE_ENABLE_ALL;
    ComPtr<ID3D10BlendState> additive;
    D3D10_BLEND_DESC mixed = blend;  // target 1 written but not blended: one blend for all is refused
    mixed.RenderTargetWriteMask[1] = D3D10_COLOR_WRITE_ENABLE_ALL;
    EXPECT_EQ(device->CreateBlendState(&mixed, additive.GetAddressOf()), E_NOTIMPL);
    EXPECT_NE(std::string(GetLastErrorMessage()).find("BlendEnable[1] = FALSE unlike BlendEnable[0]"), std::string::npos) << GetLastErrorMessage();
    ASSERT_EQ(device->CreateBlendState(&blend, additive.GetAddressOf()), S_OK) << GetLastErrorMessage();
    D3D10_DEPTH_STENCIL_DESC ds;
    ds.DepthFunc = D3D10_COMPARISON_LESS_EQUAL;  // the same depth passes again
    ComPtr<ID3D10DepthStencilState> lessEqual;
    ASSERT_EQ(device->CreateDepthStencilState(&ds, lessEqual.GetAddressOf()), S_OK) << GetLastErrorMessage();
    const float factor[4] = {0, 0, 0, 0};
    device->OMSetBlendState(additive.Get(), factor, 0xffffffff);
    device->OMSetDepthStencilState(lessEqual.Get(), 0);
    ASSERT_EQ(technique->GetPassByIndex(0)->Apply(0), S_OK);
    device->DrawIndexed(6, 0, 0);
    ASSERT_STREQ(GetLastErrorMessage(), "");

    const std::vector<float> colors = readFloats(device.Get(), color.Get()), normals = readFloats(device.Get(), normal.Get());
    int inside = 0;
    for (UINT y = 0; y < kSize; ++y)
        for (UINT x = 0; x < kSize; ++x) {
            // The pixel centre in NDC, back through projection, view and world to the quad's (x, y).
            const double nx = (x + 0.5) / kSize * 2 - 1, ny = 1 - (y + 0.5) / kSize * 2;
            const double qx = ((nx / 2 + 0.5) - 0.25) / 0.5, qy = (ny - 0.25) / 0.5;
            float expectedColor[4] = {0, 0, 0, 0}, expectedNormal[4] = {0, 0, 0, 0};
            if (std::abs(qx) < 1 && std::abs(qy) < 1) {
                ++inside;
                const double u = (qx + 1) / 2, v = (1 - qy) / 2;
                const std::uint32_t t = kTexels[std::min(1, int(v * 2)) * 2 + std::min(1, int(u * 2))];
                for (int c = 0; c < 4; ++c) expectedColor[c] = 2 * float((t >> (8 * c)) & 0xff) / 255.0f * tint[c];
                expectedNormal[2] = -1;
                expectedNormal[3] = 1;
            }
            for (int c = 0; c < 4; ++c) {
                const std::size_t i = (std::size_t(y) * kSize + x) * 4 + std::size_t(c);
                ASSERT_NEAR(colors[i], expectedColor[c], 1e-5) << "colour " << x << "," << y << " channel " << c;
                ASSERT_NEAR(normals[i], expectedNormal[c], 1e-6) << "normal " << x << "," << y << " channel " << c;
            }
        }
    EXPECT_EQ(inside, 12 * 8);  // NDC x in [-1, 0.5] (the rest is clipped), y in [-0.25, 0.75]
}

TEST_F(D3D10Test, SwapChainBackBufferIsARenderTarget) {
    ComPtr<ID3D10Texture2D> backBuffer;
    ASSERT_EQ(swapChain->GetBuffer(0, IID_ID3D10Texture2D, reinterpret_cast<void**>(backBuffer.GetAddressOf())), S_OK) << GetLastErrorMessage();
    D3D10_TEXTURE2D_DESC desc;
    backBuffer->GetDesc(&desc);
    EXPECT_EQ(desc.Width, kSize);
    EXPECT_EQ(desc.Format, DXGI_FORMAT_R32G32B32A32_FLOAT);
    ComPtr<ID3D10RenderTargetView> view;
    ASSERT_EQ(device->CreateRenderTargetView(backBuffer.Get(), nullptr, view.GetAddressOf()), S_OK) << GetLastErrorMessage();
    const float color[4] = {0.25f, 0.5f, 0.75f, 1};
    device->ClearRenderTargetView(view.Get(), color);
    EXPECT_EQ(swapChain->Present(0, 0), S_OK);
    EXPECT_EQ(swapChain->PresentCount(), 1u);
    const std::vector<float> texels = readFloats(device.Get(), backBuffer.Get());
    for (std::size_t i = 0; i < texels.size(); ++i) ASSERT_EQ(texels[i], color[i % 4]) << "texel " << i / 4;
    void* other = nullptr;
    EXPECT_EQ(swapChain->GetBuffer(1, IID_ID3D10Texture2D, &other), E_INVALIDARG);
    EXPECT_NE(std::string(GetLastErrorMessage()).find("Buffer = 1"), std::string::npos) << GetLastErrorMessage();
    EXPECT_EQ(swapChain->SetFullscreenState(TRUE, nullptr), S_FALSE);
}

TEST_F(D3D10Test, ABrokenEffectFileLeavesTheCompilersMessage) {
    const std::string path = writeFile("fxport_d3d10_broken.fx", "float4 PS() : SV_Target { return undefinedThing; }\n"
                                                                 "technique10 T { pass P { SetPixelShader(CompileShader(ps_4_0, PS())); } }\n");
    ComPtr<ID3D10Effect> effect;
    ComPtr<ID3D10Blob> errors;
    HRESULT result = S_OK;
    EXPECT_TRUE(FAILED(D3DX10CreateEffectFromFile(path.c_str(), nullptr, nullptr, "fx_4_0", D3D10_SHADER_ENABLE_STRICTNESS, 0, device.Get(),
                                                  nullptr, nullptr, effect.GetAddressOf(), errors.GetAddressOf(), &result)));
    EXPECT_TRUE(FAILED(result));
    EXPECT_FALSE(effect);
    ASSERT_TRUE(errors);
    const std::string message(static_cast<const char*>(errors->GetBufferPointer()), errors->GetBufferSize());
    EXPECT_NE(message.find("fxport_d3d10_broken.fx"), std::string::npos) << message;
    EXPECT_NE(message.find("undefinedThing"), std::string::npos) << message;
    EXPECT_EQ(D3DX10CreateEffectFromFile(path.c_str(), nullptr, nullptr, "vs_4_0", 0, 0, device.Get(), nullptr, nullptr, effect.GetAddressOf(),
                                         nullptr, nullptr),
              E_INVALIDARG);
    EXPECT_NE(std::string(GetLastErrorMessage()).find("pProfile = vs_4_0"), std::string::npos) << GetLastErrorMessage();
}

}  // namespace
}  // namespace d3d10test

namespace d3d10test {
namespace {

// Seed 004's two passes with the tutorial's own effects (hlsl/rastertek, read in place): the
// DeferredBuffersClass's targets made from its descriptions, deferred.fx drawing a quad turned 60
// degrees about y into the colour and normal targets, then light.fx on a full-screen window
// reading both through their SRVs into the swap chain's back buffer. Each back-buffer pixel is
// compared with the CPU's colour * saturate(dot(normal, -lightDirection)).
TEST_F(D3D10Test, TheTutorialsDeferredAndLightEffectsDrawWhatTheCpuComputes) {
    // D3D10Test's swap chain is R32G32B32A32_FLOAT; the tutorial reads its result back the same way.
    ComPtr<ID3D10Effect> deferred, light;
    ComPtr<ID3D10Blob> errors;
    ASSERT_EQ(D3DX10CreateEffectFromFile(L"hlsl/rastertek/deferred.fx", nullptr, nullptr, "fx_4_0", D3D10_SHADER_ENABLE_STRICTNESS, 0, device.Get(),
                                         nullptr, nullptr, deferred.GetAddressOf(), errors.GetAddressOf(), nullptr),
              S_OK)
        << GetLastErrorMessage() << " (run from the source tree)";
    ASSERT_EQ(D3DX10CreateEffectFromFile(L"hlsl/rastertek/light.fx", nullptr, nullptr, "fx_4_0", D3D10_SHADER_ENABLE_STRICTNESS, 0, device.Get(),
                                         nullptr, nullptr, light.GetAddressOf(), errors.GetAddressOf(), nullptr),
              S_OK)
        << GetLastErrorMessage();

    // DeferredBuffersClass::Initialize.
    ComPtr<ID3D10RenderTargetView> colorView, normalView;
    ComPtr<ID3D10ShaderResourceView> colorResource, normalResource;
    ComPtr<ID3D10Texture2D> color = floatTarget(colorView, colorResource), normal = floatTarget(normalView, normalResource);
    D3D10_TEXTURE2D_DESC depthBufferDesc;
    depthBufferDesc.Width = depthBufferDesc.Height = kSize;
    depthBufferDesc.MipLevels = 1;
    depthBufferDesc.ArraySize = 1;
    depthBufferDesc.Format = DXGI_FORMAT_D24_UNORM_S8_UINT;
    depthBufferDesc.Usage = D3D10_USAGE_DEFAULT;
    depthBufferDesc.BindFlags = D3D10_BIND_DEPTH_STENCIL;
    ComPtr<ID3D10Texture2D> depthStencilBuffer;
    ASSERT_EQ(device->CreateTexture2D(&depthBufferDesc, nullptr, depthStencilBuffer.GetAddressOf()), S_OK) << GetLastErrorMessage();
    D3D10_DEPTH_STENCIL_VIEW_DESC depthStencilViewDesc;
    depthStencilViewDesc.Format = DXGI_FORMAT_D24_UNORM_S8_UINT;
    depthStencilViewDesc.ViewDimension = D3D10_DSV_DIMENSION_TEXTURE2D;
    ComPtr<ID3D10DepthStencilView> depthStencilView;
    ASSERT_EQ(device->CreateDepthStencilView(depthStencilBuffer.Get(), &depthStencilViewDesc, depthStencilView.GetAddressOf()), S_OK);

    // ModelClass / TextureClass: a unit quad facing -z, and a one-texel texture.
    struct VertexType {
        float position[3], texture[2], normal[3];
    };
    const VertexType quad[4] = {{{-0.5f, 0.5f, 0}, {0, 0}, {0, 0, -1}}, {{0.5f, 0.5f, 0}, {1, 0}, {0, 0, -1}},
                                {{0.5f, -0.5f, 0}, {1, 1}, {0, 0, -1}}, {{-0.5f, -0.5f, 0}, {0, 1}, {0, 0, -1}}};
    const std::uint32_t indices[6] = {0, 1, 2, 0, 2, 3};
    auto makeBuffer = [&](const void* data, UINT bytes, UINT bind) {
        D3D10_BUFFER_DESC desc;
        desc.Usage = D3D10_USAGE_DEFAULT;
        desc.ByteWidth = bytes;
        desc.BindFlags = bind;
        D3D10_SUBRESOURCE_DATA init;
        init.pSysMem = data;
        ComPtr<ID3D10Buffer> b;
        EXPECT_EQ(device->CreateBuffer(&desc, &init, b.GetAddressOf()), S_OK) << GetLastErrorMessage();
        return b;
    };
    ComPtr<ID3D10Buffer> modelVertices = makeBuffer(quad, sizeof quad, D3D10_BIND_VERTEX_BUFFER);
    ComPtr<ID3D10Buffer> modelIndices = makeBuffer(indices, sizeof indices, D3D10_BIND_INDEX_BUFFER);
    const std::uint32_t texel = 0xff3264c8u;  // (200, 100, 50, 255)
    D3D10_TEXTURE2D_DESC td;
    td.Width = td.Height = 1;
    td.MipLevels = 1;
    td.ArraySize = 1;
    td.Format = DXGI_FORMAT_R8G8B8A8_UNORM;
    td.BindFlags = D3D10_BIND_SHADER_RESOURCE;
    D3D10_SUBRESOURCE_DATA init;
    init.pSysMem = &texel;
    init.SysMemPitch = 4;
    ComPtr<ID3D10Texture2D> texture;
    ASSERT_EQ(device->CreateTexture2D(&td, &init, texture.GetAddressOf()), S_OK) << GetLastErrorMessage();
    ComPtr<ID3D10ShaderResourceView> textureView;
    ASSERT_EQ(device->CreateShaderResourceView(texture.Get(), nullptr, textureView.GetAddressOf()), S_OK);

    // DeferredShaderClass: layout from the pass, matrices, texture; RenderShader.
    auto layoutOf = [&](ID3D10EffectTechnique* technique, const D3D10_INPUT_ELEMENT_DESC* elements, UINT count) {
        D3D10_PASS_DESC passDesc;
        EXPECT_EQ(technique->GetPassByIndex(0)->GetDesc(&passDesc), S_OK) << GetLastErrorMessage();
        ComPtr<ID3D10InputLayout> layout;
        EXPECT_EQ(device->CreateInputLayout(elements, count, passDesc.pIAInputSignature, passDesc.IAInputSignatureSize, layout.GetAddressOf()), S_OK)
            << GetLastErrorMessage();
        return layout;
    };
    const D3D10_INPUT_ELEMENT_DESC polygonLayout[3] = {
        {"POSITION", 0, DXGI_FORMAT_R32G32B32_FLOAT, 0, 0, D3D10_INPUT_PER_VERTEX_DATA, 0},
        {"TEXCOORD", 0, DXGI_FORMAT_R32G32_FLOAT, 0, D3D10_APPEND_ALIGNED_ELEMENT, D3D10_INPUT_PER_VERTEX_DATA, 0},
        {"NORMAL", 0, DXGI_FORMAT_R32G32B32_FLOAT, 0, D3D10_APPEND_ALIGNED_ELEMENT, D3D10_INPUT_PER_VERTEX_DATA, 0},
    };
    ID3D10EffectTechnique* deferredTechnique = deferred->GetTechniqueByName("DeferredTechnique");
    ComPtr<ID3D10InputLayout> deferredLayout = layoutOf(deferredTechnique, polygonLayout, 3);
    const float c = 0.5f, s = std::sqrt(3.0f) / 2;  // 60 degrees: D3DXMatrixRotationY's rows
    const float world[16] = {c, 0, -s, 0, 0, 1, 0, 0, s, 0, c, 0, 0, 0, 0, 1};
    const float view[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0.5f, 1};  // z + 0.5: inside [0, 1]
    const float identity[16] = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
    deferred->GetVariableByName("worldMatrix")->AsMatrix()->SetMatrix(world);
    deferred->GetVariableByName("viewMatrix")->AsMatrix()->SetMatrix(view);
    deferred->GetVariableByName("projectionMatrix")->AsMatrix()->SetMatrix(identity);
    ASSERT_EQ(deferred->GetVariableByName("shaderTexture")->AsShaderResource()->SetResource(textureView.Get()), S_OK) << GetLastErrorMessage();

    // DeferredBuffersClass::SetRenderTargets / ClearRenderTargets, then the model.
    ID3D10RenderTargetView* targets[2] = {colorView.Get(), normalView.Get()};
    device->OMSetRenderTargets(2, targets, depthStencilView.Get());
    D3D10_VIEWPORT viewport;
    viewport.Width = kSize;
    viewport.Height = kSize;
    device->RSSetViewports(1, &viewport);
    const float black[4] = {0, 0, 0, 0};
    device->ClearRenderTargetView(colorView.Get(), black);
    device->ClearRenderTargetView(normalView.Get(), black);
    device->ClearDepthStencilView(depthStencilView.Get(), D3D10_CLEAR_DEPTH, 1.0f, 0);
    const UINT stride = sizeof(VertexType), offset = 0;
    device->IASetVertexBuffers(0, 1, modelVertices.GetAddressOfConst(), &stride, &offset);
    device->IASetIndexBuffer(modelIndices.Get(), DXGI_FORMAT_R32_UINT, 0);
    device->IASetPrimitiveTopology(D3D10_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    device->IASetInputLayout(deferredLayout.Get());
    ASSERT_EQ(deferredTechnique->GetPassByIndex(0)->Apply(0), S_OK) << GetLastErrorMessage();
    device->DrawIndexed(6, 0, 0);
    ASSERT_STREQ(GetLastErrorMessage(), "");

    // D3DClass::SetBackBufferRenderTarget, then LightShaderClass over an OrthoWindowClass quad
    // covering the screen (identity matrices: the window's corners are NDC's).
    ComPtr<ID3D10Texture2D> backBuffer;
    ASSERT_EQ(swapChain->GetBuffer(0, IID_ID3D10Texture2D, reinterpret_cast<void**>(backBuffer.GetAddressOf())), S_OK);
    ComPtr<ID3D10RenderTargetView> backBufferView;
    ASSERT_EQ(device->CreateRenderTargetView(backBuffer.Get(), nullptr, backBufferView.GetAddressOf()), S_OK);
    device->OMSetRenderTargets(1, backBufferView.GetAddressOfConst(), nullptr);
    device->ClearRenderTargetView(backBufferView.Get(), black);
    struct WindowVertex {
        float position[3], texture[2];
    };
    const WindowVertex window[6] = {{{-1, 1, 0}, {0, 0}}, {{1, -1, 0}, {1, 1}}, {{-1, -1, 0}, {0, 1}},
                                    {{-1, 1, 0}, {0, 0}}, {{1, 1, 0}, {1, 0}},   {{1, -1, 0}, {1, 1}}};
    const std::uint32_t windowIndices[6] = {0, 1, 2, 3, 4, 5};
    ComPtr<ID3D10Buffer> windowVertices = makeBuffer(window, sizeof window, D3D10_BIND_VERTEX_BUFFER);
    ComPtr<ID3D10Buffer> windowIndexBuffer = makeBuffer(windowIndices, sizeof windowIndices, D3D10_BIND_INDEX_BUFFER);
    const D3D10_INPUT_ELEMENT_DESC windowLayout[2] = {
        {"POSITION", 0, DXGI_FORMAT_R32G32B32_FLOAT, 0, 0, D3D10_INPUT_PER_VERTEX_DATA, 0},
        {"TEXCOORD", 0, DXGI_FORMAT_R32G32_FLOAT, 0, D3D10_APPEND_ALIGNED_ELEMENT, D3D10_INPUT_PER_VERTEX_DATA, 0},
    };
    ID3D10EffectTechnique* lightTechnique = light->GetTechniqueByName("LightTechnique");
    ComPtr<ID3D10InputLayout> lightLayout = layoutOf(lightTechnique, windowLayout, 2);
    const float lightDirection[3] = {0.6f, 0.0f, 0.8f};
    light->GetVariableByName("worldMatrix")->AsMatrix()->SetMatrix(identity);
    light->GetVariableByName("viewMatrix")->AsMatrix()->SetMatrix(identity);
    light->GetVariableByName("projectionMatrix")->AsMatrix()->SetMatrix(identity);
    light->GetVariableByName("colorTexture")->AsShaderResource()->SetResource(colorResource.Get());
    light->GetVariableByName("normalTexture")->AsShaderResource()->SetResource(normalResource.Get());
    ASSERT_EQ(light->GetVariableByName("lightDirection")->AsVector()->SetFloatVector(lightDirection), S_OK) << GetLastErrorMessage();
    const UINT windowStride = sizeof(WindowVertex);
    device->IASetVertexBuffers(0, 1, windowVertices.GetAddressOfConst(), &windowStride, &offset);
    device->IASetIndexBuffer(windowIndexBuffer.Get(), DXGI_FORMAT_R32_UINT, 0);
    device->IASetInputLayout(lightLayout.Get());
    ASSERT_EQ(lightTechnique->GetPassByIndex(0)->Apply(0), S_OK) << GetLastErrorMessage();
    device->DrawIndexed(6, 0, 0);
    ASSERT_STREQ(GetLastErrorMessage(), "");
    EXPECT_EQ(swapChain->Present(0, 0), S_OK);

    // The quad covers NDC x in [-0.25, 0.25] (cos 60 = 0.5), y in [-0.5, 0.5]: pixels 6..9 x 4..11.
    const float n[3] = {-s, 0, -c};  // (0, 0, -1) turned by the world matrix
    const float intensity = std::clamp(-(n[0] * lightDirection[0] + n[1] * lightDirection[1] + n[2] * lightDirection[2]), 0.0f, 1.0f);
    const float albedo[4] = {200 / 255.0f, 100 / 255.0f, 50 / 255.0f, 1.0f};
    const std::vector<float> pixels = readFloats(device.Get(), backBuffer.Get());
    int lit = 0;
    for (UINT y = 0; y < kSize; ++y)
        for (UINT x = 0; x < kSize; ++x) {
            const bool inside = x >= 6 && x < 10 && y >= 4 && y < 12;
            lit += inside;
            for (int ch = 0; ch < 4; ++ch) {
                const float expected = inside ? std::clamp(albedo[ch] * intensity, 0.0f, 1.0f) : 0.0f;
                ASSERT_NEAR(pixels[(std::size_t(y) * kSize + x) * 4 + std::size_t(ch)], expected, 1e-5) << x << "," << y << " channel " << ch;
            }
        }
    EXPECT_EQ(lit, 32);
}

}  // namespace
}  // namespace d3d10test
