// D3D's register slots: an explicit register(tN/sN/bN) holds; the others take the lowest free slot
// in declaration order among what the shader uses ($Globals first), as fxc allocates them. Checked
// twice: in the reflection, and by drawing with resources bound at those slots (a wrong slot
// gives another colour).
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* kVertex = R"(
float4 VS(uint id : SV_VertexID) : SV_Position
{
    // A triangle covering the whole target (clockwise on screen: D3D's front face).
    float2 p = float2(id == 1 ? 3.0 : -1.0, id == 2 ? -3.0 : 1.0);
    return float4(p, 0.5, 1);
}
)";

const char* kPixel = R"(
Texture2D Unused;                       // declared, never sampled: takes no slot
Texture2D A : register(t3);
Texture2D B;                            // t0: the lowest free
SamplerState S1 : register(s2);
SamplerState S0;                        // s0
float4 globalScale;                     // $Globals: b1 (b0 is taken by C)
cbuffer Skipped { float4 neverRead; };  // declared, never read: takes no slot
cbuffer C : register(b0) { float4 offset; };
float4 PS(float4 pos : SV_Position) : SV_Target
{
    float2 uv = float2(0.5, 0.5);
    return A.Sample(S1, uv) * globalScale + B.Sample(S0, uv) * 0.25 + offset;
}
)";

struct Slot {
    const char* name;
    D3D_SHADER_INPUT_TYPE type;
    UINT bindPoint;
};

TEST(D3D11Slots, ExplicitAndAllocatedRegistersAsFxcGivesThem) {
    ComPtr<ID3DBlob> ps = compile(kPixel, "PS", "ps_4_0", "slots.hlsl");
    ASSERT_TRUE(ps);
    ComPtr<ID3D11ShaderReflection> r;
    ASSERT_EQ(D3DReflect(ps->GetBufferPointer(), ps->GetBufferSize(), r.GetAddressOf()), S_OK) << lastError();
    const Slot expected[] = {{"A", D3D_SIT_TEXTURE, 3}, {"B", D3D_SIT_TEXTURE, 0}, {"S1", D3D_SIT_SAMPLER, 2},
                             {"S0", D3D_SIT_SAMPLER, 0}, {"C", D3D_SIT_CBUFFER, 0}, {"$Globals", D3D_SIT_CBUFFER, 1}};
    for (const Slot& s : expected) {
        D3D11_SHADER_INPUT_BIND_DESC b;
        ASSERT_EQ(r->GetResourceBindingDescByName(s.name, &b), S_OK) << s.name << ": " << lastError();
        EXPECT_EQ(b.Type, s.type) << s.name;
        EXPECT_EQ(b.BindPoint, s.bindPoint) << s.name;
    }
    D3D11_SHADER_INPUT_BIND_DESC b;
    EXPECT_EQ(r->GetResourceBindingDescByName("Unused", &b), E_INVALIDARG);
    EXPECT_EQ(r->GetResourceBindingDescByName("Skipped", &b), E_INVALIDARG);
    D3D11_SHADER_DESC desc;
    r->GetDesc(&desc);
    EXPECT_EQ(desc.BoundResources, 6u);
}

TEST(D3D11Slots, ResourcesBoundAtTheirSlotsReachTheShader) {
    Device d;
    ComPtr<ID3DBlob> vsCode = compile(kVertex, "VS", "vs_4_0", "slots_vs.hlsl");
    ComPtr<ID3DBlob> psCode = compile(kPixel, "PS", "ps_4_0", "slots.hlsl");
    ASSERT_TRUE(vsCode && psCode);

    // 1x1 textures: A (at t3) red 200, B (at t0) green 200; a decoy at t1 and t2 blue.
    const std::vector<std::uint32_t> red = {0xff0000c8u}, green = {0xff00c800u}, blue = {0xffff0000u};
    auto srvOf = [&](const std::vector<std::uint32_t>& texel) {
        ComPtr<ID3D11Texture2D> t = makeTexture(d, 1, 1, D3D11_BIND_SHADER_RESOURCE, &texel);
        ComPtr<ID3D11ShaderResourceView> v;
        EXPECT_EQ(d.device->CreateShaderResourceView(t.Get(), nullptr, v.GetAddressOf()), S_OK);
        return v;
    };
    ComPtr<ID3D11ShaderResourceView> a = srvOf(red), b = srvOf(green), decoy = srvOf(blue);
    ID3D11ShaderResourceView* views[4] = {b.Get(), decoy.Get(), decoy.Get(), a.Get()};
    d.context->PSSetShaderResources(0, 4, views);
    D3D11_SAMPLER_DESC sd;
    sd.Filter = D3D11_FILTER_MIN_MAG_MIP_POINT;
    ComPtr<ID3D11SamplerState> sampler;
    ASSERT_EQ(d.device->CreateSamplerState(&sd, sampler.GetAddressOf()), S_OK);
    ID3D11SamplerState* samplers[3] = {sampler.Get(), nullptr, sampler.Get()};
    d.context->PSSetSamplers(0, 3, samplers);

    // b0 = C.offset, b1 = $Globals.globalScale.
    auto constants = [&](float x, float y, float z, float w) {
        const float v[4] = {x, y, z, w};
        D3D11_BUFFER_DESC desc;
        desc.ByteWidth = 16;
        desc.BindFlags = D3D11_BIND_CONSTANT_BUFFER;
        D3D11_SUBRESOURCE_DATA data;
        data.pSysMem = v;
        ComPtr<ID3D11Buffer> buffer;
        EXPECT_EQ(d.device->CreateBuffer(&desc, &data, buffer.GetAddressOf()), S_OK);
        return buffer;
    };
    ComPtr<ID3D11Buffer> offset = constants(0.0f, 0.0f, 0.25f, 0.0f), scale = constants(0.5f, 0.5f, 0.5f, 1.0f);
    ID3D11Buffer* cbs[2] = {offset.Get(), scale.Get()};
    d.context->PSSetConstantBuffers(0, 2, cbs);

    ComPtr<ID3D11Texture2D> target = drawTriangleToRgba8(d, vsCode.Get(), psCode.Get(), 4, 4);
    ASSERT_EQ(lastError(), "");

    // red*0.5 + green*0.25 + (0,0,0.25,0): R = 200/255*0.5, G = 200/255*0.25, B = 0.25, A = 1*1 + 0.25 -> 1.
    const double r = 200.0 / 255 * 0.5, g = 200.0 / 255 * 0.25, bl = 0.25;
    for (const auto& p : readPixels(d, target.Get())) {
        EXPECT_NEAR(p[0], r * 255, 2.0);
        EXPECT_NEAR(p[1], g * 255, 2.0);
        EXPECT_NEAR(p[2], bl * 255, 2.0);
        EXPECT_EQ(p[3], 255);
    }
}

// MiniEngine's ModelViewerPS: textures at register(t64)..: D3D11 has t0..t127. The reflection keeps
// the registers; drawn with views bound at t64 and t100 (a decoy at t0), the shader reads those.
TEST(D3D11Slots, TextureRegistersAboveThirtyOne) {
    const char* pixel = R"(
Texture2D High : register(t64);
Texture2D Higher : register(t100);
SamplerState S : register(s0);
float4 PS(float4 pos : SV_Position) : SV_Target
{
    return High.Sample(S, float2(0.5, 0.5)) * 0.5 + Higher.Load(int3(0, 0, 0)) * 0.25;
}
)";
    Device d;
    ComPtr<ID3DBlob> vsCode = compile(kVertex, "VS", "vs_4_0", "slots_vs.hlsl");
    ComPtr<ID3DBlob> psCode = compile(pixel, "PS", "ps_5_0", "slots_high.hlsl");
    ASSERT_TRUE(vsCode && psCode) << lastError();
    ComPtr<ID3D11ShaderReflection> r;
    ASSERT_EQ(D3DReflect(psCode->GetBufferPointer(), psCode->GetBufferSize(), r.GetAddressOf()), S_OK) << lastError();
    for (const Slot& s : {Slot{"High", D3D_SIT_TEXTURE, 64}, Slot{"Higher", D3D_SIT_TEXTURE, 100}}) {
        D3D11_SHADER_INPUT_BIND_DESC b;
        ASSERT_EQ(r->GetResourceBindingDescByName(s.name, &b), S_OK) << s.name << ": " << lastError();
        EXPECT_EQ(b.BindPoint, s.bindPoint) << s.name;
    }
    const std::vector<std::uint32_t> red = {0xff0000c8u}, green = {0xff00c800u}, blue = {0xffff0000u};
    auto srvOf = [&](const std::vector<std::uint32_t>& texel) {
        ComPtr<ID3D11Texture2D> t = makeTexture(d, 1, 1, D3D11_BIND_SHADER_RESOURCE, &texel);
        ComPtr<ID3D11ShaderResourceView> v;
        EXPECT_EQ(d.device->CreateShaderResourceView(t.Get(), nullptr, v.GetAddressOf()), S_OK);
        return v;
    };
    ComPtr<ID3D11ShaderResourceView> high = srvOf(red), higher = srvOf(green), decoy = srvOf(blue);
    ID3D11ShaderResourceView* decoys[1] = {decoy.Get()};
    d.context->PSSetShaderResources(0, 1, decoys);
    d.context->PSSetShaderResources(64, 1, high.GetAddressOfConst());
    d.context->PSSetShaderResources(100, 1, higher.GetAddressOfConst());
    D3D11_SAMPLER_DESC sd;
    sd.Filter = D3D11_FILTER_MIN_MAG_MIP_POINT;
    ComPtr<ID3D11SamplerState> sampler;
    ASSERT_EQ(d.device->CreateSamplerState(&sd, sampler.GetAddressOf()), S_OK);
    d.context->PSSetSamplers(0, 1, sampler.GetAddressOfConst());
    ComPtr<ID3D11Texture2D> target = drawTriangleToRgba8(d, vsCode.Get(), psCode.Get(), 4, 4);
    ASSERT_EQ(lastError(), "");
    // red*0.5 + green*0.25: R = 200*0.5, G = 200*0.25, B = 0 (the blue decoy would show here).
    for (const auto& p : readPixels(d, target.Get())) {
        EXPECT_NEAR(p[0], 200 * 0.5, 2.0);
        EXPECT_NEAR(p[1], 200 * 0.25, 2.0);
        EXPECT_NEAR(p[2], 0, 2.0);
    }
}

}  // namespace
}  // namespace d3d11test
