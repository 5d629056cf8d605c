// Vertex element formats beyond the R32/R16/R8 families, and D3D10's rule that the input assembler
// converts nothing between integers and floats. Each test feeds one element (per instance, so every
// vertex reads the same value) to a vertex shader that passes it on unchanged (nointerpolation) to
// a pixel shader writing an R32G32B32A32 target; the texel read back is compared with what D3D's
// format documentation says the bytes mean, worked out here on the CPU.
#include <cmath>
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

struct Element {
    DXGI_FORMAT format;
    std::vector<std::uint8_t> bytes;  // one element
    std::string inputType;            // the vertex shader's input, e.g. float4
    std::string passOn;               // HLSL making the uint4/float4 the pixel shader writes from `data`
    bool uintTarget = false;          // write uint4 into R32G32B32A32_UINT, else float4 into _FLOAT
};

template <class T>
std::vector<std::uint8_t> bytesOf(const T& value) {
    std::vector<std::uint8_t> out(sizeof value);
    std::memcpy(out.data(), &value, sizeof value);
    return out;
}

// CreateInputLayout's result; on S_OK, the 16 bytes of texel (0, 0) after the draw.
HRESULT drawElement(const Element& e, std::array<std::uint32_t, 4>& texel) {
    Device d;
    const std::string out = e.uintTarget ? "uint4" : "float4";
    const std::string source = "struct VO { float4 pos : SV_Position; nointerpolation " + out + " v : V; };\n"
                               "VO vs(float2 p : POSITION, " + e.inputType + " data : DATA) {\n"
                               "    VO o; o.pos = float4(p, 0, 1); o.v = " + e.passOn + "; return o;\n}\n" +
                               out + " ps(VO i) : SV_Target { return i.v; }\n";
    ComPtr<ID3DBlob> vsCode = compile(source, "vs", "vs_5_0"), psCode = compile(source, "ps", "ps_5_0");
    if (!vsCode || !psCode) return E_FAIL;
    const D3D11_INPUT_ELEMENT_DESC layout[] = {
        {"POSITION", 0, DXGI_FORMAT_R32G32_FLOAT, 0, 0, D3D11_INPUT_PER_VERTEX_DATA, 0},
        {"DATA", 0, e.format, 1, 0, D3D11_INPUT_PER_INSTANCE_DATA, 1},
    };
    ComPtr<ID3D11InputLayout> il;
    const HRESULT hr = d.device->CreateInputLayout(layout, 2, vsCode->GetBufferPointer(), vsCode->GetBufferSize(), il.GetAddressOf());
    if (FAILED(hr)) return hr;
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    EXPECT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    EXPECT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
    const float corners[6] = {-1, 3, 3, -1, -1, -1};  // one triangle over the target (clockwise)
    std::vector<std::uint8_t> data = e.bytes;
    data.resize(16, 0);
    ComPtr<ID3D11Buffer> vb[2] = {makeBuffer(d, corners, sizeof corners, D3D11_BIND_VERTEX_BUFFER),
                                  makeBuffer(d, data.data(), UINT(data.size()), D3D11_BIND_VERTEX_BUFFER)};
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = 2;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = e.uintTarget ? DXGI_FORMAT_R32G32B32A32_UINT : DXGI_FORMAT_R32G32B32A32_FLOAT;
    desc.BindFlags = D3D11_BIND_RENDER_TARGET;
    ComPtr<ID3D11Texture2D> target;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, target.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11RenderTargetView> rtv;
    EXPECT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    D3D11_VIEWPORT viewport;
    viewport.Width = viewport.Height = 2;
    d.context->RSSetViewports(1, &viewport);
    d.context->IASetInputLayout(il.Get());
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    ID3D11Buffer* const buffers[2] = {vb[0].Get(), vb[1].Get()};
    const UINT strides[2] = {8, 16}, offsets[2] = {0, 0};
    d.context->IASetVertexBuffers(0, 2, buffers, strides, offsets);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->DrawInstanced(3, 1, 0, 0);
    EXPECT_EQ(lastError(), "");
    texel = readTexels<std::array<std::uint32_t, 4>>(d, target.Get()).at(0);
    return S_OK;
}

std::array<float, 4> asFloats(const std::array<std::uint32_t, 4>& t) {
    std::array<float, 4> f;
    std::memcpy(f.data(), t.data(), sizeof f);
    return f;
}

// An unsigned float of 5 exponent bits (bias 15) and `mantissaBits` (DXGI's R11G11B10_FLOAT), for a
// value that is a normal number of that format.
std::uint32_t smallFloat(float value, int mantissaBits) {
    int exponent = 0;
    const float fraction = std::frexp(value, &exponent);  // value = fraction * 2^exponent, fraction in [0.5, 1)
    const auto mantissa = std::uint32_t(std::lround((fraction * 2 - 1) * float(1 << mantissaBits)));
    return std::uint32_t(exponent - 1 + 15) << mantissaBits | mantissa;
}

TEST(D3D11VertexElements, B8G8R8A8ReadsBlueFromTheFirstByte) {
    const std::uint8_t bgra[4] = {10, 20, 30, 40};  // memory order: B, G, R, A
    std::array<std::uint32_t, 4> texel{};
    ASSERT_EQ(drawElement({DXGI_FORMAT_B8G8R8A8_UNORM, {bgra, bgra + 4}, "float4", "data"}, texel), S_OK) << lastError();
    const std::array<float, 4> got = asFloats(texel), want = {30 / 255.f, 20 / 255.f, 10 / 255.f, 40 / 255.f};
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[std::size_t(c)], want[std::size_t(c)], 1e-6f) << "component " << c;
}

TEST(D3D11VertexElements, R11G11B10FloatUnpacksThreeSmallFloats) {
    const float values[3] = {1.5f, 0.25f, 6.0f};
    const std::uint32_t packed = smallFloat(values[0], 6) | smallFloat(values[1], 6) << 11 | smallFloat(values[2], 5) << 22;
    std::array<std::uint32_t, 4> texel{};
    ASSERT_EQ(drawElement({DXGI_FORMAT_R11G11B10_FLOAT, bytesOf(packed), "float3", "float4(data, 1)"}, texel), S_OK) << lastError();
    const std::array<float, 4> got = asFloats(texel);
    EXPECT_EQ(got[0], values[0]);
    EXPECT_EQ(got[1], values[1]);
    EXPECT_EQ(got[2], values[2]);
    EXPECT_EQ(got[3], 1.0f);
}

TEST(D3D11VertexElements, R10G10B10A2UnormReadsTenBitChannels) {
    const std::uint32_t packed = 1023u | 512u << 10 | 1u << 20 | 2u << 30;
    std::array<std::uint32_t, 4> texel{};
    ASSERT_EQ(drawElement({DXGI_FORMAT_R10G10B10A2_UNORM, bytesOf(packed), "float4", "data"}, texel), S_OK) << lastError();
    const std::array<float, 4> got = asFloats(texel), want = {1.0f, 512 / 1023.f, 1 / 1023.f, 2 / 3.f};
    for (int c = 0; c < 4; ++c) EXPECT_NEAR(got[std::size_t(c)], want[std::size_t(c)], 1e-6f) << "component " << c;
}

// D3D10+: a float input fed 32-bit integers holds their bits (asuint gives the integers back);
// GL would convert 7 to 7.0 (0x40e00000).
TEST(D3D11VertexElements, FloatInputFedUintElementGetsTheBits) {
    const std::uint32_t values[4] = {7, 0x3f800000u, 0xffffffffu, 0x80000001u};
    for (DXGI_FORMAT format : {DXGI_FORMAT_R32G32B32A32_UINT, DXGI_FORMAT_R32G32B32A32_SINT}) {
        std::array<std::uint32_t, 4> texel{};
        ASSERT_EQ(drawElement({format, bytesOf(values), "float4", "asuint(data)", true}, texel), S_OK) << lastError();
        for (int c = 0; c < 4; ++c) EXPECT_EQ(texel[std::size_t(c)], values[c]) << "format " << format << " component " << c;
    }
    // An integer input keeps reading the integers themselves.
    std::array<std::uint32_t, 4> texel{};
    ASSERT_EQ(drawElement({DXGI_FORMAT_R32G32B32A32_UINT, bytesOf(values), "uint4", "data", true}, texel), S_OK) << lastError();
    for (int c = 0; c < 4; ++c) EXPECT_EQ(texel[std::size_t(c)], values[c]) << "component " << c;
}

TEST(D3D11VertexElements, FloatInputFedNarrowIntegersIsRefused) {
    const std::uint8_t bytes[4] = {1, 2, 3, 4};
    std::array<std::uint32_t, 4> texel{};
    EXPECT_EQ(drawElement({DXGI_FORMAT_R8G8B8A8_UINT, {bytes, bytes + 4}, "float4", "data"}, texel), E_NOTIMPL);
    EXPECT_NE(lastError().find("pInputElementDescs[1].Format = DXGI_FORMAT_R8G8B8A8_UINT"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
