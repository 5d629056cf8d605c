// SV_ClipDistance and SV_CullDistance as D3D11 has them: a vertex shader's clip distances (a float2
// at semantic index 0 and a float at index 1) cut the primitive where any interpolated distance is
// negative, pixel by pixel against the CPU's plane equations; a pixel shader reading them gets
// the interpolated values; a cull distance drops a triangle only when all its vertices are
// negative, and never cuts one.
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

constexpr UINT kSize = 16;

const char* kClip = R"(
struct VSOut {
    float4 position : SV_Position;
    float2 clip : SV_ClipDistance0;
    float clip1 : SV_ClipDistance1;
};
VSOut VS(uint id : SV_VertexID)
{
    // One triangle over the whole target.
    float2 p = float2(id == 1 ? 3.0 : -1.0, id == 2 ? -3.0 : 1.0);
    VSOut o;
    o.position = float4(p, 0, 1);
    o.clip = float2(p.x + 0.3, 0.55 - p.y);
    o.clip1 = 0.7 - p.x;
    return o;
}
float4 PS(VSOut i) : SV_Target { return float4(i.clip, i.clip1, 1); }
)";

const char* kCull = R"(
struct VSOut {
    float4 position : SV_Position;
    float cull : SV_CullDistance;
};
VSOut VS(uint id : SV_VertexID)
{
    // Two triangles: the left half of the target (ids 0-2), every distance negative; the right
    // half (ids 3-5), one vertex negative.
    static const float2 corners[6] = { {-1, 1}, {0, 1}, {-1, -1}, {0, 1}, {1, 1}, {0, -1} };
    static const float distances[6] = { -1, -2, -0.5, -1, 1, 1 };
    VSOut o;
    o.position = float4(corners[id], 0, 1);
    o.cull = distances[id];
    return o;
}
float4 PS() : SV_Target { return float4(1, 1, 1, 1); }
)";

struct ClipTest : ::testing::Test {
    Device d;
    ComPtr<ID3D11Texture2D> target;
    ComPtr<ID3D11RenderTargetView> rtv;

    void SetUp() override {
        D3D11_TEXTURE2D_DESC desc;
        desc.Width = desc.Height = kSize;
        desc.MipLevels = 1;
        desc.ArraySize = 1;
        desc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
        desc.BindFlags = D3D11_BIND_RENDER_TARGET;
        ASSERT_EQ(d.device->CreateTexture2D(&desc, nullptr, target.GetAddressOf()), S_OK) << lastError();
        ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    }
    void draw(const char* source, UINT vertices) {
        ComPtr<ID3DBlob> vsCode = compile(source, "VS", "vs_5_0", "clip.hlsl"), psCode = compile(source, "PS", "ps_5_0", "clip.hlsl");
        ASSERT_TRUE(vsCode && psCode);
        ComPtr<ID3D11VertexShader> vs;
        ComPtr<ID3D11PixelShader> ps;
        ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
        ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
        const FLOAT clear[4] = {-9, -9, -9, 0};
        d.context->ClearRenderTargetView(rtv.Get(), clear);
        d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
        D3D11_VIEWPORT vp;
        vp.Width = vp.Height = kSize;
        d.context->RSSetViewports(1, &vp);
        d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
        d.context->VSSetShader(vs.Get(), nullptr, 0);
        d.context->PSSetShader(ps.Get(), nullptr, 0);
        d.context->Draw(vertices, 0);
        ASSERT_EQ(lastError(), "");
    }
    std::vector<std::array<float, 4>> texels() { return readTexels<std::array<float, 4>>(d, target.Get()); }
};

TEST_F(ClipTest, ClipDistancesCutWhereAnyIsNegativeAndReachThePixelShader) {
    draw(kClip, 3);
    const std::vector<std::array<float, 4>> got = texels();
    int drawn = 0;
    for (UINT y = 0; y < kSize; ++y)
        for (UINT x = 0; x < kSize; ++x) {
            // The pixel centre in NDC (D3D: y up, row 0 at the top); the planes are linear, so the
            // interpolated distances are the plane equations there. No centre lies on a plane.
            const double nx = (x + 0.5) / (kSize / 2.0) - 1.0, ny = 1.0 - (y + 0.5) / (kSize / 2.0);
            const double c0 = nx + 0.3, c1 = 0.55 - ny, c2 = 0.7 - nx;
            const bool kept = c0 >= 0 && c1 >= 0 && c2 >= 0;
            const std::array<float, 4>& t = got[std::size_t(y) * kSize + x];
            if (!kept) {
                EXPECT_EQ(t[0], -9.0f) << "pixel " << x << "," << y << " should be clipped";
                continue;
            }
            ++drawn;
            // D3D11 (and GL hardware) snap vertices to 1/256 of a pixel before interpolating: the
            // distances, one NDC unit per unit, may be off by that much (the H100 is by 1/512 pixel).
            const double snap = (2.0 / kSize) / 256;
            EXPECT_NEAR(t[0], c0, snap) << "pixel " << x << "," << y;
            EXPECT_NEAR(t[1], c1, snap) << "pixel " << x << "," << y;
            EXPECT_NEAR(t[2], c2, snap) << "pixel " << x << "," << y;
        }
    EXPECT_EQ(drawn, 8 * 12);  // columns 6..13 (x in [-0.3, 0.7]), rows 4..15 (y <= 0.55)
}

TEST_F(ClipTest, ReflectionListsTheClipDistanceRegister) {
    ComPtr<ID3DBlob> vs = compile(kClip, "VS", "vs_5_0", "clip.hlsl");
    ASSERT_TRUE(vs);
    ComPtr<ID3D11ShaderReflection> r;
    ASSERT_EQ(D3DReflect(vs->GetBufferPointer(), vs->GetBufferSize(), r.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_DESC desc;
    ASSERT_EQ(r->GetDesc(&desc), S_OK);
    ASSERT_EQ(desc.OutputParameters, 2u);  // SV_Position, then the three distances in one register
    D3D11_SIGNATURE_PARAMETER_DESC p;
    ASSERT_EQ(r->GetOutputParameterDesc(1, &p), S_OK);
    EXPECT_EQ(std::string(p.SemanticName), "SV_ClipDistance");
    EXPECT_EQ(p.SystemValueType, D3D_NAME_CLIP_DISTANCE);
    EXPECT_EQ(p.Mask, 0x7);
}

TEST_F(ClipTest, CullDistancesDropWholeTrianglesOnly) {
    draw(kCull, 6);
    const std::vector<std::array<float, 4>> got = texels();
    for (UINT y = 0; y < kSize; ++y)
        for (UINT x = 0; x < kSize; ++x) {
            // The right triangle (0,1) (1,1) (0,-1) in NDC covers centres with nx >= 0 and
            // nx <= (1 + ny) / 2; the left one is culled.
            const double nx = (x + 0.5) / (kSize / 2.0) - 1.0, ny = 1.0 - (y + 0.5) / (kSize / 2.0);
            const bool inside = nx >= 0 && nx <= (1.0 + ny) / 2.0;
            EXPECT_EQ(got[std::size_t(y) * kSize + x][0], inside ? 1.0f : -9.0f) << "pixel " << x << "," << y;
        }
}

}  // namespace
}  // namespace d3d11test
