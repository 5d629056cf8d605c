// Full draws, written as a D3D11 tutorial writes them, read back and compared with a CPU computation
// of the same math (2/255): a textured, lit quad with a constant buffer per stage, an SRV, a point
// sampler and a depth buffer; a full-screen quad behind it that the depth test must hide; a
// back-facing triangle that CULL_BACK must drop (front faces are clockwise); D3D's pixel centres
// (pixel (x, y) is sampled at x + 0.5, y + 0.5 from the top left).
#include <cmath>
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* kShaders = R"(
cbuffer PerObject : register(b0)
{
    float4x4 Transform;   // column_major (the HLSL default): the host uploads the transpose
    float Depth;
};
cbuffer Lighting : register(b0)   // the pixel stage's own b0
{
    float3 LightDirection;
    float Ambient;
    float4 Tint;
};
Texture2D Diffuse : register(t0);
SamplerState PointClamp : register(s0);

struct VSIn { float3 position : POSITION; float3 normal : NORMAL; float2 uv : TEXCOORD0; };
struct PSIn { float4 position : SV_Position; float3 normal : NORMAL; float2 uv : TEXCOORD0; };

PSIn VS(VSIn v)
{
    PSIn o;
    float4 p = mul(float4(v.position, 1), Transform);
    o.position = float4(p.xy, Depth, 1);
    o.normal = v.normal;
    o.uv = v.uv;
    return o;
}

float4 PS(PSIn i) : SV_Target
{
    float light = Ambient + saturate(dot(normalize(i.normal), -LightDirection));
    return Diffuse.Sample(PointClamp, i.uv) * light * Tint;
}
)";

struct Vertex {
    float position[3];
    float normal[3];
    float uv[2];
};
struct PerObject {
    float transform[16];  // transposed (column_major HLSL)
    float depth;
    float pad[3];
};
struct Lighting {
    float lightDirection[3];
    float ambient;
    float tint[4];
};

constexpr int kSize = 32;

// A row-vector transform (x' = s*x + tx, y' = s*y + ty), stored transposed as D3D code stores it.
PerObject perObject(float s, float tx, float ty, float depth) {
    const float m[4][4] = {{s, 0, 0, 0}, {0, s, 0, 0}, {0, 0, 1, 0}, {tx, ty, 0, 1}};
    PerObject o{};
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c) o.transform[c * 4 + r] = m[r][c];
    o.depth = depth;
    return o;
}

struct DrawTest : ::testing::Test {
    Device d;
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;
    ComPtr<ID3D11InputLayout> layout;

    void SetUp() override {
        ComPtr<ID3DBlob> vsCode = compile(kShaders, "VS", "vs_5_0", "draw.hlsl");
        ComPtr<ID3DBlob> psCode = compile(kShaders, "PS", "ps_5_0", "draw.hlsl");
        ASSERT_TRUE(vsCode && psCode);
        ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
        ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
        const D3D11_INPUT_ELEMENT_DESC elements[] = {
            {"POSITION", 0, DXGI_FORMAT_R32G32B32_FLOAT, 0, 0, D3D11_INPUT_PER_VERTEX_DATA, 0},
            {"NORMAL", 0, DXGI_FORMAT_R32G32B32_FLOAT, 0, D3D11_APPEND_ALIGNED_ELEMENT, D3D11_INPUT_PER_VERTEX_DATA, 0},
            {"TEXCOORD", 0, DXGI_FORMAT_R32G32_FLOAT, 0, D3D11_APPEND_ALIGNED_ELEMENT, D3D11_INPUT_PER_VERTEX_DATA, 0},
        };
        ASSERT_EQ(d.device->CreateInputLayout(elements, 3, vsCode->GetBufferPointer(), vsCode->GetBufferSize(), layout.GetAddressOf()), S_OK)
            << lastError();
    }

    template <class T>
    ComPtr<ID3D11Buffer> buffer(const T* data, UINT bytes, UINT bind, D3D11_USAGE usage = D3D11_USAGE_DEFAULT) {
        D3D11_BUFFER_DESC desc;
        desc.ByteWidth = bytes;
        desc.BindFlags = bind;
        desc.Usage = usage;
        desc.CPUAccessFlags = usage == D3D11_USAGE_DYNAMIC ? UINT(D3D11_CPU_ACCESS_WRITE) : 0u;
        D3D11_SUBRESOURCE_DATA init;
        init.pSysMem = data;
        ComPtr<ID3D11Buffer> b;
        EXPECT_EQ(d.device->CreateBuffer(&desc, data ? &init : nullptr, b.GetAddressOf()), S_OK) << lastError();
        return b;
    }
    template <class T>
    void write(ID3D11Buffer* dynamic, const T& value) {
        D3D11_MAPPED_SUBRESOURCE m;
        ASSERT_EQ(d.context->Map(dynamic, 0, D3D11_MAP_WRITE_DISCARD, 0, &m), S_OK) << lastError();
        std::memcpy(m.pData, &value, sizeof value);
        d.context->Unmap(dynamic, 0);
    }
};

// The 4x4 texture: texel (x, y) = (40 + 60x, 30 + 70y, 200 - 40x, 255).
std::uint32_t texel(int x, int y) {
    const std::uint32_t r = std::uint32_t(40 + 60 * x), g = std::uint32_t(30 + 70 * y), b = std::uint32_t(200 - 40 * x);
    return r | g << 8 | b << 16 | 0xffu << 24;
}

TEST_F(DrawTest, TexturedLitQuadWithDepthAndCullingMatchesTheCpu) {
    // Resources, as a tutorial's InitScene makes them.
    std::vector<std::uint32_t> texels(16);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 4; ++x) texels[std::size_t(y * 4 + x)] = texel(x, y);
    ComPtr<ID3D11Texture2D> texture = makeTexture(d, 4, 4, D3D11_BIND_SHADER_RESOURCE, &texels);
    ComPtr<ID3D11ShaderResourceView> srv;
    ASSERT_EQ(d.device->CreateShaderResourceView(texture.Get(), nullptr, srv.GetAddressOf()), S_OK);
    const std::vector<std::uint32_t> white = {0xffffffffu};
    ComPtr<ID3D11Texture2D> whiteTexture = makeTexture(d, 1, 1, D3D11_BIND_SHADER_RESOURCE, &white);
    ComPtr<ID3D11ShaderResourceView> whiteSrv;
    ASSERT_EQ(d.device->CreateShaderResourceView(whiteTexture.Get(), nullptr, whiteSrv.GetAddressOf()), S_OK);
    D3D11_SAMPLER_DESC sd;
    sd.Filter = D3D11_FILTER_MIN_MAG_MIP_POINT;
    ComPtr<ID3D11SamplerState> sampler;
    ASSERT_EQ(d.device->CreateSamplerState(&sd, sampler.GetAddressOf()), S_OK);

    // A quad in the z = 0 plane facing the viewer (normal -z), clockwise on screen, indexed.
    const Vertex quad[4] = {{{-1, 1, 0}, {0, 0, -1}, {0, 0}}, {{1, 1, 0}, {0, 0, -1}, {1, 0}},
                            {{1, -1, 0}, {0, 0, -1}, {1, 1}}, {{-1, -1, 0}, {0, 0, -1}, {0, 1}}};
    const std::uint16_t indices[6] = {0, 1, 2, 0, 2, 3};
    // A triangle wound counter-clockwise on screen: a back face.
    const Vertex back[3] = {{{-1, 1, 0}, {0, 0, -1}, {0, 0}}, {{-1, -1, 0}, {0, 0, -1}, {0, 1}}, {{1, 1, 0}, {0, 0, -1}, {1, 0}}};
    ComPtr<ID3D11Buffer> vertices = buffer(quad, sizeof quad, D3D11_BIND_VERTEX_BUFFER);
    ComPtr<ID3D11Buffer> backVertices = buffer(back, sizeof back, D3D11_BIND_VERTEX_BUFFER);
    ComPtr<ID3D11Buffer> indexBuffer = buffer(indices, sizeof indices, D3D11_BIND_INDEX_BUFFER);
    ComPtr<ID3D11Buffer> objectCb = buffer<PerObject>(nullptr, sizeof(PerObject), D3D11_BIND_CONSTANT_BUFFER, D3D11_USAGE_DYNAMIC);
    ComPtr<ID3D11Buffer> lightCb = buffer<Lighting>(nullptr, sizeof(Lighting), D3D11_BIND_CONSTANT_BUFFER, D3D11_USAGE_DYNAMIC);

    // Targets: colour and a D24S8 depth buffer.
    ComPtr<ID3D11Texture2D> target = makeTexture(d, kSize, kSize, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK);
    D3D11_TEXTURE2D_DESC dd;
    dd.Width = dd.Height = kSize;
    dd.MipLevels = 1;
    dd.ArraySize = 1;
    dd.Format = DXGI_FORMAT_D24_UNORM_S8_UINT;
    dd.BindFlags = D3D11_BIND_DEPTH_STENCIL;
    ComPtr<ID3D11Texture2D> depth;
    ASSERT_EQ(d.device->CreateTexture2D(&dd, nullptr, depth.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11DepthStencilView> dsv;
    ASSERT_EQ(d.device->CreateDepthStencilView(depth.Get(), nullptr, dsv.GetAddressOf()), S_OK) << lastError();

    // The frame.
    const FLOAT clear[4] = {0, 0, 0, 1};
    d.context->ClearRenderTargetView(rtv.Get(), clear);
    d.context->ClearDepthStencilView(dsv.Get(), D3D11_CLEAR_DEPTH | D3D11_CLEAR_STENCIL, 1.0f, 0);
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), dsv.Get());
    D3D11_VIEWPORT vp;
    vp.Width = vp.Height = kSize;
    d.context->RSSetViewports(1, &vp);
    d.context->IASetInputLayout(layout.Get());
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    const UINT stride = sizeof(Vertex), offset = 0;
    d.context->IASetVertexBuffers(0, 1, vertices.GetAddressOfConst(), &stride, &offset);
    d.context->IASetIndexBuffer(indexBuffer.Get(), DXGI_FORMAT_R16_UINT, 0);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->VSSetConstantBuffers(0, 1, objectCb.GetAddressOfConst());
    d.context->PSSetConstantBuffers(0, 1, lightCb.GetAddressOfConst());
    d.context->PSSetSamplers(0, 1, sampler.GetAddressOfConst());

    // 1: the textured quad, near (z 0.5), scaled 0.75 and moved right and down.
    const float s = 0.75f, tx = 0.125f, ty = -0.125f;
    write(objectCb.Get(), perObject(s, tx, ty, 0.5f));
    const float direction[3] = {0.0f, 0.6f, 0.8f};  // normalized; n . -L = 0.8 for n = (0,0,-1)
    write(lightCb.Get(), Lighting{{direction[0], direction[1], direction[2]}, 0.1f, {1, 1, 1, 1}});
    d.context->PSSetShaderResources(0, 1, srv.GetAddressOfConst());
    d.context->DrawIndexed(6, 0, 0);
    ASSERT_EQ(lastError(), "");
    // 2: a full-screen quad behind it (z 0.7), white texture, tinted: hidden where quad 1 is.
    write(objectCb.Get(), perObject(1, 0, 0, 0.7f));
    write(lightCb.Get(), Lighting{{direction[0], direction[1], direction[2]}, 0.1f, {0.2f, 0.4f, 0.6f, 1}});
    d.context->PSSetShaderResources(0, 1, whiteSrv.GetAddressOfConst());
    d.context->DrawIndexed(6, 0, 0);
    // 3: a back-facing triangle in front of everything (z 0.1): culled by the default CULL_BACK.
    write(objectCb.Get(), perObject(1, 0, 0, 0.1f));
    write(lightCb.Get(), Lighting{{direction[0], direction[1], direction[2]}, 1.0f, {1, 0, 1, 1}});
    d.context->IASetVertexBuffers(0, 1, backVertices.GetAddressOfConst(), &stride, &offset);
    d.context->Draw(3, 0);
    ASSERT_EQ(lastError(), "");

    // The CPU: pixel (x, y) samples at its centre; NDC from the top left, y up.
    const double light = 0.1 + 0.8;
    const auto pixels = readPixels(d, target.Get());
    int quadPixels = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const double nx = (x + 0.5) / kSize * 2 - 1, ny = 1 - (y + 0.5) / kSize * 2;
            const double lx = (nx - tx) / s, ly = (ny - ty) / s;  // quad-local position
            double expected[4];
            if (std::abs(lx) < 1 && std::abs(ly) < 1) {
                ++quadPixels;
                const double u = (lx + 1) / 2, v = (1 - ly) / 2;
                const std::uint32_t t = texel(std::min(3, int(u * 4)), std::min(3, int(v * 4)));
                for (int c = 0; c < 3; ++c) expected[c] = std::min(1.0, double((t >> (8 * c)) & 0xff) / 255 * light);
                expected[3] = std::min(1.0, light);
            } else {
                const double tint[4] = {0.2, 0.4, 0.6, 1};
                for (int c = 0; c < 4; ++c) expected[c] = std::min(1.0, light * tint[c]);
            }
            const auto& p = pixels[std::size_t(y * kSize + x)];
            for (int c = 0; c < 4; ++c)
                ASSERT_NEAR(p[std::size_t(c)], expected[c] * 255, 2.0) << "pixel " << x << "," << y << " channel " << c;
        }
    EXPECT_EQ(quadPixels, 24 * 24);  // 0.75 of 32 pixels each way
}

TEST_F(DrawTest, InstancedDrawsRepeatTheDraw) {
    // DrawInstanced with no per-instance data: every instance draws the same quad; with
    // additive blending two instances give twice the colour.
    const Vertex quad[4] = {{{-1, 1, 0}, {0, 0, -1}, {0, 0}}, {{1, 1, 0}, {0, 0, -1}, {1, 0}},
                            {{-1, -1, 0}, {0, 0, -1}, {0, 1}}, {{1, -1, 0}, {0, 0, -1}, {1, 1}}};
    ComPtr<ID3D11Buffer> vertices = buffer(quad, sizeof quad, D3D11_BIND_VERTEX_BUFFER);
    const PerObject object = perObject(1, 0, 0, 0.5f);
    ComPtr<ID3D11Buffer> objectCb = buffer(&object, sizeof object, D3D11_BIND_CONSTANT_BUFFER);
    const Lighting lighting{{0, 0, 1}, 0.0f, {0.25f, 0.125f, 0.0f, 0.25f}};  // light 1 (n . -L = 1)
    ComPtr<ID3D11Buffer> lightCb = buffer(&lighting, sizeof lighting, D3D11_BIND_CONSTANT_BUFFER);
    const std::vector<std::uint32_t> white = {0xffffffffu};
    ComPtr<ID3D11Texture2D> whiteTexture = makeTexture(d, 1, 1, D3D11_BIND_SHADER_RESOURCE, &white);
    ComPtr<ID3D11ShaderResourceView> srv;
    ASSERT_EQ(d.device->CreateShaderResourceView(whiteTexture.Get(), nullptr, srv.GetAddressOf()), S_OK);
    ComPtr<ID3D11Texture2D> target = makeTexture(d, 8, 8, D3D11_BIND_RENDER_TARGET);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK);
    D3D11_BLEND_DESC bd;
    bd.RenderTarget[0].BlendEnable = TRUE;
    bd.RenderTarget[0].DestBlend = D3D11_BLEND_ONE;
    bd.RenderTarget[0].DestBlendAlpha = D3D11_BLEND_ONE;
    ComPtr<ID3D11BlendState> additive;
    ASSERT_EQ(d.device->CreateBlendState(&bd, additive.GetAddressOf()), S_OK);

    const FLOAT clear[4] = {0, 0, 0, 0};
    d.context->ClearRenderTargetView(rtv.Get(), clear);
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    d.context->OMSetBlendState(additive.Get(), nullptr, 0xffffffffu);
    D3D11_VIEWPORT vp;
    vp.Width = vp.Height = 8;
    d.context->RSSetViewports(1, &vp);
    d.context->IASetInputLayout(layout.Get());
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLESTRIP);
    const UINT stride = sizeof(Vertex), offset = 0;
    d.context->IASetVertexBuffers(0, 1, vertices.GetAddressOfConst(), &stride, &offset);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->VSSetConstantBuffers(0, 1, objectCb.GetAddressOfConst());
    d.context->PSSetConstantBuffers(0, 1, lightCb.GetAddressOfConst());
    d.context->PSSetShaderResources(0, 1, srv.GetAddressOfConst());
    d.context->DrawInstanced(4, 3, 0, 0);
    ASSERT_EQ(lastError(), "");
    for (const auto& p : readPixels(d, target.Get())) {
        EXPECT_NEAR(p[0], 0.75 * 255, 2.0);
        EXPECT_NEAR(p[1], 0.375 * 255, 2.0);
        EXPECT_NEAR(p[2], 0, 2.0);
        EXPECT_NEAR(p[3], 0.75 * 255, 2.0);
    }
}

TEST_F(DrawTest, DrawsD3DIgnoresSayWhy) {
    // No render target bound: nothing drawn, and the message says so.
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->IASetInputLayout(layout.Get());
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->Draw(3, 0);
    EXPECT_NE(lastError().find("no vertex buffer"), std::string::npos) << lastError();
    d.context->ClearState();
    d.context->Draw(3, 0);
    EXPECT_NE(lastError().find("topology"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
