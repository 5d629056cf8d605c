// The input assembler beyond one buffer, and region copies, checked pixel by pixel against a CPU
// computation: vertices from three slots (a per-vertex corner, per-instance offsets stepping every
// instance, per-instance colours stepping every second instance: InstanceDataStepRate 2), drawn
// instanced and indexed-instanced with a StartInstanceLocation; CopySubresourceRegion between
// buffers (GPU to GPU, GPU to staging) and between texture rectangles; the layout's invalid
// slot descriptions answered with the field and value.
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* kInstanced = R"(
struct VSIn {
    float2 corner : POSITION;      // slot 0, per vertex: the square's corner in pixels
    float2 offset : TEXCOORD1;     // slot 1, per instance
    float4 color : COLOR0;         // slot 2, per two instances
};
struct PSIn { float4 position : SV_Position; float4 color : COLOR0; };

PSIn VS(VSIn v)
{
    float2 pixel = v.corner + v.offset;
    PSIn o;
    o.position = float4(pixel.x / 16 - 1, 1 - pixel.y / 16, 0, 1);   // a 32x32 target
    o.color = v.color;
    return o;
}
float4 PS(PSIn i) : SV_Target { return i.color; }
)";

constexpr UINT kSize = 32;

struct InstancingTest : ::testing::Test {
    Device d;
    ComPtr<ID3DBlob> vsCode;
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;

    void SetUp() override {
        vsCode = compile(kInstanced, "VS", "vs_5_0", "instanced.hlsl");
        ComPtr<ID3DBlob> psCode = compile(kInstanced, "PS", "ps_5_0", "instanced.hlsl");
        ASSERT_TRUE(vsCode && psCode);
        ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
        ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
    }
    HRESULT layout(const D3D11_INPUT_ELEMENT_DESC* elements, UINT count, ID3D11InputLayout** out) {
        return d.device->CreateInputLayout(elements, count, vsCode->GetBufferPointer(), vsCode->GetBufferSize(), out);
    }
    template <class T>
    ComPtr<ID3D11Buffer> buffer(const T* data, UINT bytes, UINT bind) {
        D3D11_BUFFER_DESC desc;
        desc.ByteWidth = bytes;
        desc.BindFlags = bind;
        D3D11_SUBRESOURCE_DATA init;
        init.pSysMem = data;
        ComPtr<ID3D11Buffer> b;
        EXPECT_EQ(d.device->CreateBuffer(&desc, &init, b.GetAddressOf()), S_OK) << lastError();
        return b;
    }
};

const D3D11_INPUT_ELEMENT_DESC kLayout[] = {
    {"POSITION", 0, DXGI_FORMAT_R32G32_FLOAT, 0, 0, D3D11_INPUT_PER_VERTEX_DATA, 0},
    {"TEXCOORD", 1, DXGI_FORMAT_R32G32_FLOAT, 1, 0, D3D11_INPUT_PER_INSTANCE_DATA, 1},
    {"COLOR", 0, DXGI_FORMAT_R8G8B8A8_UNORM, 2, 0, D3D11_INPUT_PER_INSTANCE_DATA, 2},
};

TEST_F(InstancingTest, ThreeSlotsAndStepRatesDrawWhatTheCpuComputes) {
    ComPtr<ID3D11InputLayout> il;
    ASSERT_EQ(layout(kLayout, 3, il.GetAddressOf()), S_OK) << lastError();
    // A 6x6 square (two clockwise triangles), eight instances on two rows, six colours.
    const float corners[8] = {0, 0, 6, 0, 6, 6, 0, 6};
    const std::uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
    const float offsets[16] = {1, 1, 9, 1, 17, 1, 25, 1, 1, 17, 9, 17, 17, 17, 25, 17};
    const std::uint32_t colours[6] = {0xff0000ffu, 0xff00ff00u, 0xffff0000u, 0xff00ffffu, 0xffffff00u, 0xff808080u};
    ComPtr<ID3D11Buffer> vb[3] = {buffer(corners, sizeof corners, D3D11_BIND_VERTEX_BUFFER), buffer(offsets, sizeof offsets, D3D11_BIND_VERTEX_BUFFER),
                                  buffer(colours, sizeof colours, D3D11_BIND_VERTEX_BUFFER)};
    ComPtr<ID3D11Buffer> ib = buffer(indices, sizeof indices, D3D11_BIND_INDEX_BUFFER);
    ComPtr<ID3D11Texture2D> target = makeTexture(d, kSize, kSize, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK);
    const FLOAT clear[4] = {0, 0, 0, 0};
    d.context->ClearRenderTargetView(rtv.Get(), clear);
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    D3D11_VIEWPORT vp;
    vp.Width = vp.Height = kSize;
    d.context->RSSetViewports(1, &vp);
    d.context->IASetInputLayout(il.Get());
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    ID3D11Buffer* const buffers[3] = {vb[0].Get(), vb[1].Get(), vb[2].Get()};
    const UINT strides[3] = {8, 8, 4}, zero[3] = {0, 0, 0};
    d.context->IASetVertexBuffers(0, 3, buffers, strides, zero);
    d.context->IASetIndexBuffer(ib.Get(), DXGI_FORMAT_R16_UINT, 0);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    // The top row: instances 0..3 (colours 0, 0, 1, 1).
    d.context->DrawIndexedInstanced(6, 4, 0, 0, 0);
    ASSERT_EQ(lastError(), "");
    // The bottom row: instances 0..3 from StartInstanceLocation 4, through an offset binding of
    // slot 1 that skips nothing (offset 0) and a second, non-indexed draw.
    const float square[12] = {0, 0, 6, 0, 6, 6, 0, 0, 6, 6, 0, 6};
    ComPtr<ID3D11Buffer> triangles = buffer(square, sizeof square, D3D11_BIND_VERTEX_BUFFER);
    d.context->IASetVertexBuffers(0, 1, triangles.GetAddressOfConst(), strides, zero);
    d.context->DrawInstanced(6, 4, 0, 4);
    ASSERT_EQ(lastError(), "");

    // D3D: instance i of a draw reads slot data StartInstanceLocation + i / InstanceDataStepRate.
    std::vector<std::uint32_t> expected(kSize * kSize, 0);
    for (UINT instance = 0; instance < 8; ++instance) {
        const UINT start = instance < 4 ? 0 : 4, i = instance - start;
        const UINT offsetIndex = start + i, colourIndex = start + i / 2;
        const int ox = int(offsets[offsetIndex * 2]), oy = int(offsets[offsetIndex * 2 + 1]);
        for (int y = oy; y < oy + 6; ++y)
            for (int x = ox; x < ox + 6; ++x) expected[std::size_t(y) * kSize + std::size_t(x)] = colours[colourIndex];
    }
    std::vector<std::array<std::uint8_t, 4>> pixels = readPixels(d, target.Get());
    int differing = 0;
    for (std::size_t p = 0; p < pixels.size(); ++p) {
        const std::uint32_t got = pixels[p][0] | pixels[p][1] << 8 | pixels[p][2] << 16 | std::uint32_t(pixels[p][3]) << 24;
        if (got != expected[p] && differing++ < 8) ADD_FAILURE() << "pixel " << p % kSize << "," << p / kSize << ": " << std::hex << got << " != " << expected[p];
    }
    EXPECT_EQ(differing, 0);
}

// SV_InstanceID counts the draw's instances from 0 whatever StartInstanceLocation is (D3D; GL's
// gl_InstanceID too, Vulkan's InstanceIndex, which glslang maps it to, adds the base). Two
// instances of one full-target triangle: the second, id 1, is what stays.
TEST(D3D11SystemValues, InstanceIdCountsFromZeroAfterAStartInstanceLocation) {
    Device d;
    const char* source = R"(
        struct V { float4 p : SV_Position; nointerpolation uint id : INSTANCE; };
        V VS(uint v : SV_VertexID, uint i : SV_InstanceID) {
            V o; o.p = float4(v == 1 ? 3.0 : -1.0, v == 2 ? -3.0 : 1.0, 0, 1); o.id = i; return o;
        }
        float4 PS(V i) : SV_Target { return float4(i.id, 0, 0, 1); })";
    ComPtr<ID3DBlob> vsCode = compile(source, "VS", "vs_5_0", "instance_id.hlsl"), psCode = compile(source, "PS", "ps_5_0", "instance_id.hlsl");
    ASSERT_TRUE(vsCode && psCode);
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
    D3D11_TEXTURE2D_DESC desc{};
    desc.Width = desc.Height = 4;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    desc.SampleDesc.Count = 1;
    desc.BindFlags = D3D11_BIND_RENDER_TARGET;
    ComPtr<ID3D11Texture2D> target;
    ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, target.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    D3D11_VIEWPORT vp{};
    vp.Width = vp.Height = 4;
    vp.MaxDepth = 1;
    d.context->RSSetViewports(1, &vp);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->DrawInstanced(3, 2, 0, 5);
    ASSERT_EQ(lastError(), "");
    for (const std::array<float, 4>& t : readTexels<std::array<float, 4>>(d, target.Get())) ASSERT_EQ(t, (std::array<float, 4>{1, 0, 0, 1}));
}

TEST_F(InstancingTest, InvalidSlotDescriptionsNameTheFieldAndValue) {
    auto rejected = [&](HRESULT code, D3D11_INPUT_ELEMENT_DESC changed, int index, const std::string& words) {
        D3D11_INPUT_ELEMENT_DESC elements[3] = {kLayout[0], kLayout[1], kLayout[2]};
        elements[index] = changed;
        ComPtr<ID3D11InputLayout> il;
        EXPECT_EQ(layout(elements, 3, il.GetAddressOf()), code) << words;
        EXPECT_NE(lastError().find(words), std::string::npos) << lastError();
    };
    D3D11_INPUT_ELEMENT_DESC e = kLayout[1];
    e.InputSlot = 32;
    rejected(E_INVALIDARG, e, 1, "pInputElementDescs[1].InputSlot = 32");
    e = kLayout[1];
    e.InstanceDataStepRate = 0;
    rejected(E_NOTIMPL, e, 1, "pInputElementDescs[1].InstanceDataStepRate = 0 with PER_INSTANCE_DATA");
    e = kLayout[0];
    e.InstanceDataStepRate = 3;
    rejected(E_INVALIDARG, e, 0, "pInputElementDescs[0].InstanceDataStepRate = 3 with PER_VERTEX_DATA");
    e = kLayout[2];
    e.InputSlot = 1;  // slot 1 already steps once per instance
    e.AlignedByteOffset = 8;
    rejected(E_INVALIDARG, e, 2, "differ from an earlier element of InputSlot 1");
    e = kLayout[2];
    e.InputSlotClass = D3D11_INPUT_CLASSIFICATION(7);
    rejected(E_INVALIDARG, e, 2, "InputSlotClass = 7");

    // A slot the layout reads with no buffer there: nothing drawn, and the slot named.
    ComPtr<ID3D11InputLayout> il;
    ASSERT_EQ(layout(kLayout, 3, il.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11Texture2D> target = makeTexture(d, 4, 4, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK);
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    d.context->IASetInputLayout(il.Get());
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    const float corners[6] = {0, 0, 6, 0, 6, 6};
    ComPtr<ID3D11Buffer> vb = buffer(corners, sizeof corners, D3D11_BIND_VERTEX_BUFFER);
    const UINT stride = 8, offset = 0;
    d.context->IASetVertexBuffers(0, 1, vb.GetAddressOfConst(), &stride, &offset);
    d.context->DrawInstanced(3, 1, 0, 0);
    EXPECT_NE(lastError().find("reads slot 1 and no vertex buffer is set there"), std::string::npos) << lastError();
}

TEST(D3D11Copies, CopySubresourceRegionMovesTheBytesAndTexelsAsked) {
    Device d;
    // Buffers: GPU to GPU, then GPU to staging (the read-back path).
    std::uint32_t words[16];
    for (std::uint32_t i = 0; i < 16; ++i) words[i] = 100 + i;
    D3D11_BUFFER_DESC desc;
    desc.ByteWidth = sizeof words;
    desc.BindFlags = D3D11_BIND_VERTEX_BUFFER;
    D3D11_SUBRESOURCE_DATA init;
    init.pSysMem = words;
    ComPtr<ID3D11Buffer> source, middle, staging;
    ASSERT_EQ(d.device->CreateBuffer(&desc, &init, source.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreateBuffer(&desc, nullptr, middle.GetAddressOf()), S_OK) << lastError();
    desc.BindFlags = 0;
    desc.Usage = D3D11_USAGE_STAGING;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_READ;
    ASSERT_EQ(d.device->CreateBuffer(&desc, nullptr, staging.GetAddressOf()), S_OK) << lastError();
    D3D11_BOX box;
    box.left = 8;  // words 2..5
    box.right = 24;
    d.context->CopySubresourceRegion(middle.Get(), 0, 40, 0, 0, source.Get(), 0, &box);  // to words 10..13
    ASSERT_EQ(lastError(), "");
    box.left = 36;  // words 9..14 of the middle buffer: 0, 102..105, 0
    box.right = 60;
    d.context->CopySubresourceRegion(staging.Get(), 0, 4, 0, 0, middle.Get(), 0, &box);  // to words 1..6
    ASSERT_EQ(lastError(), "");
    D3D11_MAPPED_SUBRESOURCE mapped;
    ASSERT_EQ(d.context->Map(staging.Get(), 0, D3D11_MAP_READ, 0, &mapped), S_OK) << lastError();
    std::uint32_t got[16];
    std::memcpy(got, mapped.pData, sizeof got);
    d.context->Unmap(staging.Get(), 0);
    const std::uint32_t expected[16] = {0, 0, 102, 103, 104, 105, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    for (int i = 0; i < 16; ++i) EXPECT_EQ(got[i], expected[i]) << "word " << i;
    box.right = 68;
    d.context->CopySubresourceRegion(staging.Get(), 0, 4, 0, 0, middle.Get(), 0, &box);
    EXPECT_NE(lastError().find("bytes [36, 68) of a 64-byte buffer"), std::string::npos) << lastError();

    // Textures: a 4x3 rectangle of an 8x8 texture to (1, 4) of another.
    std::vector<std::uint32_t> texels(64);
    for (std::uint32_t i = 0; i < 64; ++i) texels[i] = 0xff000000u | (i * 3) | (i * 2) << 8;
    ComPtr<ID3D11Texture2D> from = makeTexture(d, 8, 8, D3D11_BIND_SHADER_RESOURCE, &texels);
    ComPtr<ID3D11Texture2D> to = makeTexture(d, 8, 8, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(to.Get(), nullptr, rtv.GetAddressOf()), S_OK);
    const FLOAT clear[4] = {0, 0, 0, 0};
    d.context->ClearRenderTargetView(rtv.Get(), clear);
    D3D11_BOX rect;
    rect.left = 2;
    rect.top = 1;
    rect.right = 6;
    rect.bottom = 4;
    d.context->CopySubresourceRegion(to.Get(), 0, 1, 4, 0, from.Get(), 0, &rect);
    ASSERT_EQ(lastError(), "");
    std::vector<std::array<std::uint8_t, 4>> pixels = readPixels(d, to.Get());
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const bool inside = x >= 1 && x < 5 && y >= 4 && y < 7;
            const std::uint32_t want = inside ? texels[std::size_t((y - 4 + 1) * 8 + (x - 1 + 2))] : 0;
            const auto& p = pixels[std::size_t(y * 8 + x)];
            EXPECT_EQ(p[0] | p[1] << 8 | p[2] << 16 | std::uint32_t(p[3]) << 24, want) << "pixel " << x << "," << y;
        }
    d.context->CopySubresourceRegion(to.Get(), 0, 6, 6, 0, from.Get(), 0, &rect);
    EXPECT_NE(lastError().find("overruns destination level 0"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
