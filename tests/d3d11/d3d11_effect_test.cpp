// The D3DX11 effects framework: an .fx compiled with an fx_5_0 target, variables set through
// AsMatrix/AsVector/AsScalar/AsShaderResource, the input layout made from a pass's signature, and
// GetPassByIndex(0)->Apply(0, context) before a draw; the pixels are compared with a CPU
// computation of the effect's math (2/255). Invalid names and wrong-kind variables fail as in Effects11.
#include <cmath>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* kEffect = R"(
float4x4 World;
float4 Color;
float Intensity;
Texture2D Diffuse;
SamplerState PointClamp { Filter = MIN_MAG_MIP_POINT; AddressU = Clamp; AddressV = Clamp; };

struct VSIn { float3 position : POSITION; float2 uv : TEXCOORD0; };
struct PSIn { float4 position : SV_Position; float2 uv : TEXCOORD0; };

PSIn VS(VSIn v)
{
    PSIn o;
    o.position = mul(float4(v.position, 1), World);
    o.uv = v.uv;
    return o;
}
float4 PS(PSIn i) : SV_Target { return Diffuse.Sample(PointClamp, i.uv) * Color * Intensity; }

technique11 Textured
{
    pass P0
    {
        SetVertexShader(CompileShader(vs_5_0, VS()));
        SetGeometryShader(NULL);
        SetPixelShader(CompileShader(ps_5_0, PS()));
    }
}
)";

struct Vertex {
    float position[3];
    float uv[2];
};

// 2x2 texels.
const std::uint32_t kTexels[4] = {0xff2040c0u, 0xffc04020u, 0xff80ff10u, 0xff10e0ffu};

TEST(D3D11Effect, VariablesAndPassApplyDrawWhatTheCpuComputes) {
    Device d;
    ComPtr<ID3DBlob> fx = compile(kEffect, nullptr, "fx_5_0", "textured.fx");
    ASSERT_TRUE(fx);
    ComPtr<ID3DX11Effect> effect;
    ASSERT_EQ(D3DX11CreateEffectFromMemory(fx->GetBufferPointer(), fx->GetBufferSize(), 0, d.device.Get(), effect.GetAddressOf()), S_OK)
        << lastError();
    ID3DX11EffectTechnique* technique = effect->GetTechniqueByName("Textured");
    ASSERT_TRUE(technique->IsValid());
    D3DX11_TECHNIQUE_DESC td;
    ASSERT_EQ(technique->GetDesc(&td), S_OK);
    EXPECT_EQ(td.Passes, 1u);
    ID3DX11EffectPass* pass = technique->GetPassByIndex(0);

    // The input layout from the pass's signature, as Effects11 code makes it.
    D3DX11_PASS_DESC pd;
    ASSERT_EQ(pass->GetDesc(&pd), S_OK) << lastError();
    const D3D11_INPUT_ELEMENT_DESC elements[] = {
        {"POSITION", 0, DXGI_FORMAT_R32G32B32_FLOAT, 0, 0, D3D11_INPUT_PER_VERTEX_DATA, 0},
        {"TEXCOORD", 0, DXGI_FORMAT_R32G32_FLOAT, 0, 12, D3D11_INPUT_PER_VERTEX_DATA, 0},
    };
    ComPtr<ID3D11InputLayout> layout;
    ASSERT_EQ(d.device->CreateInputLayout(elements, 2, pd.pIAInputSignature, pd.IAInputSignatureSize, layout.GetAddressOf()), S_OK)
        << lastError();

    std::vector<std::uint32_t> texels(std::begin(kTexels), std::end(kTexels));
    ComPtr<ID3D11Texture2D> texture = makeTexture(d, 2, 2, D3D11_BIND_SHADER_RESOURCE, &texels);
    ComPtr<ID3D11ShaderResourceView> srv;
    ASSERT_EQ(d.device->CreateShaderResourceView(texture.Get(), nullptr, srv.GetAddressOf()), S_OK);

    // World: scale 0.5, then move by (0.25, 0.25); row by row as XMFLOAT4X4 holds it.
    const float world[16] = {0.5f, 0, 0, 0, 0, 0.5f, 0, 0, 0, 0, 1, 0, 0.25f, 0.25f, 0, 1};
    const float color[4] = {1.0f, 0.5f, 0.25f, 1.0f};
    ASSERT_EQ(effect->GetVariableByName("World")->AsMatrix()->SetMatrix(world), S_OK) << lastError();
    ASSERT_EQ(effect->GetVariableByName("Color")->AsVector()->SetFloatVector(color), S_OK) << lastError();
    ASSERT_EQ(effect->GetVariableByName("Intensity")->AsScalar()->SetFloat(0.8f), S_OK) << lastError();
    ASSERT_EQ(effect->GetVariableByName("Diffuse")->AsShaderResource()->SetResource(srv.Get()), S_OK) << lastError();
    float back[16];
    ASSERT_EQ(effect->GetVariableByName("World")->AsMatrix()->GetMatrix(back), S_OK);
    EXPECT_EQ(back[12], 0.25f);

    // Invalid objects and the wrong kind fail, as in Effects11.
    EXPECT_FALSE(effect->GetVariableByName("Nope")->IsValid());
    EXPECT_EQ(effect->GetVariableByName("Nope")->AsScalar()->SetFloat(1), E_FAIL);
    EXPECT_EQ(effect->GetVariableByName("Color")->AsMatrix()->SetMatrix(world), E_FAIL);
    EXPECT_NE(lastError().find("'Color'"), std::string::npos) << lastError();
    EXPECT_FALSE(effect->GetTechniqueByName("Missing")->IsValid());
    EXPECT_EQ(technique->GetPassByIndex(3)->Apply(0, d.context.Get()), E_FAIL);

    const Vertex quad[4] = {{{-1, 1, 0}, {0, 0}}, {{1, 1, 0}, {1, 0}}, {{-1, -1, 0}, {0, 1}}, {{1, -1, 0}, {1, 1}}};
    D3D11_BUFFER_DESC bd;
    bd.ByteWidth = sizeof quad;
    bd.BindFlags = D3D11_BIND_VERTEX_BUFFER;
    D3D11_SUBRESOURCE_DATA data;
    data.pSysMem = quad;
    ComPtr<ID3D11Buffer> vertices;
    ASSERT_EQ(d.device->CreateBuffer(&bd, &data, vertices.GetAddressOf()), S_OK);
    constexpr int kSize = 16;
    ComPtr<ID3D11Texture2D> target = makeTexture(d, kSize, kSize, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK);
    const FLOAT clear[4] = {0, 0, 0, 0};
    d.context->ClearRenderTargetView(rtv.Get(), clear);
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    D3D11_VIEWPORT vp;
    vp.Width = vp.Height = kSize;
    d.context->RSSetViewports(1, &vp);
    d.context->IASetInputLayout(layout.Get());
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLESTRIP);
    const UINT stride = sizeof(Vertex), offset = 0;
    d.context->IASetVertexBuffers(0, 1, vertices.GetAddressOfConst(), &stride, &offset);
    ASSERT_EQ(pass->Apply(0, d.context.Get()), S_OK) << lastError();
    d.context->Draw(4, 0);
    ASSERT_EQ(lastError(), "");

    int inside = 0;
    const auto pixels = readPixels(d, target.Get());
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double nx = (x + 0.5) / kSize * 2 - 1, ny = 1 - (y + 0.5) / kSize * 2;
            const double lx = (nx - 0.25) / 0.5, ly = (ny - 0.25) / 0.5;
            double expected[4] = {0, 0, 0, 0};
            if (std::abs(lx) < 1 && std::abs(ly) < 1) {
                ++inside;
                const int tx = std::min(1, int((lx + 1) / 2 * 2)), ty = std::min(1, int((1 - ly) / 2 * 2));
                const std::uint32_t t = kTexels[ty * 2 + tx];
                for (int c = 0; c < 4; ++c) expected[c] = double((t >> (8 * c)) & 0xff) / 255 * color[c] * 0.8;
            }
            for (int c = 0; c < 4; ++c)
                ASSERT_NEAR(pixels[std::size_t(y * kSize + x)][std::size_t(c)], expected[c] * 255, 2.0) << x << "," << y << " channel " << c;
        }
    EXPECT_EQ(inside, 64);

    // A shader set afterwards replaces the pass; with no vertex shader the draw is refused.
    d.context->VSSetShader(nullptr, nullptr, 0);
    d.context->Draw(4, 0);
    EXPECT_NE(lastError().find("no vertex shader"), std::string::npos) << lastError();
}

TEST(D3D11Effect, ASingleShaderBlobIsNotAnEffect) {
    Device d;
    ComPtr<ID3DBlob> vs = compile(kEffect, "VS", "vs_5_0", "textured.fx");
    ASSERT_TRUE(vs);
    ComPtr<ID3DX11Effect> effect;
    EXPECT_EQ(D3DX11CreateEffectFromMemory(vs->GetBufferPointer(), vs->GetBufferSize(), 0, d.device.Get(), effect.GetAddressOf()),
              E_INVALIDARG);
    EXPECT_NE(lastError().find("fx_5_0"), std::string::npos) << lastError();
}

// fxc accepts an effect without a technique from fx_4_0 on (variables only, as for an effect
// pool); fx_2_0 refuses it (FX1003). D3DX11CreateEffectFromFile compiles for fx_5_0, and D3DCompile
// applies the fx_* target it is given.
TEST(D3D11Effect, EffectsWithoutTechniquesFollowTheFxProfile) {
    Device d;
    const std::string source = "float4 tint;\nmatrix world;\n";
    ComPtr<ID3DBlob> code, errors;
    ASSERT_EQ(D3DCompile(source.data(), source.size(), "pool.fx", nullptr, nullptr, nullptr, "fx_5_0", 0, 0, code.GetAddressOf(), errors.GetAddressOf()),
              S_OK)
        << lastError();
    ComPtr<ID3DX11Effect> effect;
    ASSERT_EQ(D3DX11CreateEffectFromMemory(code->GetBufferPointer(), code->GetBufferSize(), 0, d.device.Get(), effect.GetAddressOf()), S_OK)
        << lastError();
    D3DX11_EFFECT_DESC desc;
    ASSERT_EQ(effect->GetDesc(&desc), S_OK);
    EXPECT_EQ(desc.Techniques, 0u);
    EXPECT_EQ(D3DCompile(source.data(), source.size(), "pool.fx", nullptr, nullptr, nullptr, "fx_2_0", 0, 0, code.GetAddressOf(), errors.GetAddressOf()),
              E_FAIL);
    EXPECT_NE(lastError().find("FX1003"), std::string::npos) << lastError();

    const std::string path = (std::filesystem::temp_directory_path() / "fxport_effect_pool.fx").string();
    std::ofstream(path) << source;
    ComPtr<ID3DX11Effect> fromFile;
    EXPECT_EQ(D3DX11CreateEffectFromFile(path.c_str(), 0, d.device.Get(), fromFile.GetAddressOf()), S_OK) << lastError();
    std::remove(path.c_str());
}

}  // namespace
}  // namespace d3d11test
