// The tessellation factors a hull shader hands the tessellator, as D3D computes them: the
// ProcessTri/QuadTessFactors intrinsics (glslang declares them without a body) under each
// partitioning, against a CPU reference of D3D's rules (tess_factor_intrinsics.h), and a patch
// constant array (`float2 extra[2] : TEXCOORD1`, elements at TEXCOORD1 and TEXCOORD2). The domain
// shader passes the factors it receives to the pixel shader, flat; one pixel is read back.
#include <algorithm>
#include <cmath>
#include <string>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* kFactors = R"(
cbuffer Raw : register(b0) { float3 RawEdges; float InsideScale; };   // the hull stage's b0
struct ControlPoint { float3 pos : TEXCOORD0; float4 unused : SV_Position; };
struct PatchConstants {
    float edges[3] : SV_TessFactor;
    float inside : SV_InsideTessFactor;
    float2 extra[2] : TEXCOORD1;
    float unrounded : TEXCOORD5;
};
struct DomainOut { float4 pos : SV_Position; nointerpolation float4 factors : COLOR0; nointerpolation float4 more : COLOR1; };

ControlPoint VS(float3 pos : POSITION) { ControlPoint o; o.pos = pos; o.unused = float4(pos, 1); return o; }

PatchConstants Constants(InputPatch<ControlPoint, 3> patch)
{
    PatchConstants o;
    float3 e;
    float i, u;
    PROCESS(RawEdges, InsideScale, e, i, u);
    o.edges[0] = e.x; o.edges[1] = e.y; o.edges[2] = e.z;
    o.inside = i;
    o.unrounded = u;
    o.extra[0] = float2(10, 11);
    o.extra[1] = float2(12, 13);
    return o;
}

[domain("tri")]
[partitioning(PARTITIONING)]
[outputtopology("triangle_cw")]
[outputcontrolpoints(3)]
[patchconstantfunc("Constants")]
ControlPoint HS(InputPatch<ControlPoint, 3> patch, uint i : SV_OutputControlPointID) { return patch[i]; }

[domain("tri")]
DomainOut DS(PatchConstants pc, float3 bary : SV_DomainLocation, const OutputPatch<ControlPoint, 3> patch)
{
    DomainOut o;
    o.pos = float4(patch[0].pos * bary.x + patch[1].pos * bary.y + patch[2].pos * bary.z, 1);
    o.factors = float4(pc.edges[0], pc.edges[1], pc.edges[2], pc.inside);
    o.more = float4(pc.unrounded, pc.extra[0].y, pc.extra[1].x, pc.extra[1].y);
    return o;
}

float4 PS(DomainOut i) : SV_Target { return i.factors; }
float4 PSMore(DomainOut i) : SV_Target { return i.more; }
)";

enum class Partitioning { Integer, Pow2, FractionalOdd, FractionalEven };
enum class Op { Avg, Max, Min };

// D3D's rules, written from the D3D11 tessellator's ranges and DXC's lowering of the intrinsics:
// edges clamped to the partitioning's range and rounded up (integer: whole, pow2: power of two);
// the inside factor the op over the edges (each at least 1) times the scale (clamped to [0, 1]),
// clamped and rounded alike; fractional_odd takes min(avg or max, 3) where that rounds below 3.
struct Expected {
    float edges[3];
    float inside;
    float unrounded;
};
float clampFactor(Partitioning p, float f) {
    return std::min(std::max(f, p == Partitioning::FractionalEven ? 2.0f : 1.0f), p == Partitioning::FractionalOdd ? 63.0f : 64.0f);
}
float roundFactor(Partitioning p, float f) {
    if (p == Partitioning::Integer) return std::ceil(f);
    if (p == Partitioning::Pow2) return std::exp2(std::ceil(std::log2(f)));
    return f;
}
Expected reference(Partitioning p, Op op, const float raw[3], float scale) {
    Expected e;
    for (int k = 0; k < 3; ++k) e.edges[k] = roundFactor(p, clampFactor(p, raw[k]));
    const float c[3] = {std::max(raw[0], 1.0f), std::max(raw[1], 1.0f), std::max(raw[2], 1.0f)};
    const float avg = (c[0] + c[1] + c[2]) * (1.0f / 3.0f);
    const float combined = op == Op::Avg ? avg : op == Op::Max ? std::max({c[0], c[1], c[2]}) : std::min({c[0], c[1], c[2]});
    e.unrounded = clampFactor(p, combined * std::min(std::max(scale, 0.0f), 1.0f));
    e.inside = roundFactor(p, e.unrounded);
    if (p == Partitioning::FractionalOdd && e.inside < 3) {
        e.unrounded = e.inside = std::min(clampFactor(p, op == Op::Max ? combined : avg), 3.0f);
    }
    return e;
}

struct Drawn {
    std::array<float, 4> factors, more;
};

// The hull shader of `partitioning` calling `intrinsic` on raw edges `raw` and `scale`; what the
// domain shader received.
Drawn draw(const char* partitioning, const char* intrinsic, const float raw[3], float scale) {
    Device d;
    const std::string source = std::string("#define PARTITIONING \"") + partitioning + "\"\n#define PROCESS " + intrinsic + "\n" + kFactors;
    ComPtr<ID3DBlob> vsCode = compile(source, "VS", "vs_5_0", "factors.hlsl"), hsCode = compile(source, "HS", "hs_5_0", "factors.hlsl");
    ComPtr<ID3DBlob> dsCode = compile(source, "DS", "ds_5_0", "factors.hlsl"), psCode = compile(source, "PS", "ps_5_0", "factors.hlsl");
    ComPtr<ID3DBlob> moreCode = compile(source, "PSMore", "ps_5_0", "factors.hlsl");
    if (!vsCode || !hsCode || !dsCode || !psCode || !moreCode) return {};
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11HullShader> hs;
    ComPtr<ID3D11DomainShader> ds;
    ComPtr<ID3D11PixelShader> ps, psMore;
    ComPtr<ID3D11InputLayout> layout;
    EXPECT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    EXPECT_EQ(d.device->CreateHullShader(hsCode->GetBufferPointer(), hsCode->GetBufferSize(), nullptr, hs.GetAddressOf()), S_OK) << lastError();
    EXPECT_EQ(d.device->CreateDomainShader(dsCode->GetBufferPointer(), dsCode->GetBufferSize(), nullptr, ds.GetAddressOf()), S_OK) << lastError();
    EXPECT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
    EXPECT_EQ(d.device->CreatePixelShader(moreCode->GetBufferPointer(), moreCode->GetBufferSize(), nullptr, psMore.GetAddressOf()), S_OK)
        << lastError();
    const D3D11_INPUT_ELEMENT_DESC element = {"POSITION", 0, DXGI_FORMAT_R32G32B32_FLOAT, 0, 0, D3D11_INPUT_PER_VERTEX_DATA, 0};
    EXPECT_EQ(d.device->CreateInputLayout(&element, 1, vsCode->GetBufferPointer(), vsCode->GetBufferSize(), layout.GetAddressOf()), S_OK)
        << lastError();
    // One triangle over the whole viewport, clockwise as D3D's front faces are.
    const float corners[9] = {-1, -1, 0, -1, 3, 0, 3, -1, 0};
    ComPtr<ID3D11Buffer> vertices = makeBuffer(d, corners, sizeof corners, D3D11_BIND_VERTEX_BUFFER);
    const float constants[4] = {raw[0], raw[1], raw[2], scale};
    ComPtr<ID3D11Buffer> cb = makeBuffer(d, constants, sizeof constants, D3D11_BIND_CONSTANT_BUFFER);
    D3D11_TEXTURE2D_DESC desc = {};
    desc.Width = desc.Height = 4;
    desc.MipLevels = desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    desc.SampleDesc.Count = 1;
    desc.BindFlags = D3D11_BIND_RENDER_TARGET;
    ComPtr<ID3D11Texture2D> target;
    ComPtr<ID3D11RenderTargetView> view;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, target.GetAddressOf()), S_OK) << lastError();
    EXPECT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, view.GetAddressOf()), S_OK) << lastError();
    const D3D11_VIEWPORT viewport = {0, 0, 4, 4, 0, 1};
    d.context->RSSetViewports(1, &viewport);
    d.context->OMSetRenderTargets(1, view.GetAddressOfConst(), nullptr);
    d.context->IASetInputLayout(layout.Get());
    const UINT stride = 12, offset = 0;
    d.context->IASetVertexBuffers(0, 1, vertices.GetAddressOfConst(), &stride, &offset);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_3_CONTROL_POINT_PATCHLIST);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->HSSetShader(hs.Get(), nullptr, 0);
    d.context->HSSetConstantBuffers(0, 1, cb.GetAddressOfConst());
    d.context->DSSetShader(ds.Get(), nullptr, 0);
    Drawn out;
    for (auto [pixel, result] : {std::pair{ps.Get(), &out.factors}, std::pair{psMore.Get(), &out.more}}) {
        d.context->PSSetShader(pixel, nullptr, 0);
        d.context->Draw(3, 0);
        EXPECT_EQ(lastError(), "");
        *result = readTexels<std::array<float, 4>>(d, target.Get())[5];  // pixel (1, 1)
    }
    return out;
}

struct Case {
    const char* partitioning;
    Partitioning p;
    const char* intrinsic;
    Op op;
    float raw[3];
    float scale;
};

class TessFactorsTest : public ::testing::TestWithParam<Case> {};

TEST_P(TessFactorsTest, TheHullShaderHandsOnD3DsFactors) {
    const Case& c = GetParam();
    const Expected e = reference(c.p, c.op, c.raw, c.scale);
    const Drawn got = draw(c.partitioning, c.intrinsic, c.raw, c.scale);
    for (int k = 0; k < 3; ++k) EXPECT_FLOAT_EQ(got.factors[k], e.edges[k]) << "edge " << k;
    EXPECT_FLOAT_EQ(got.factors[3], e.inside) << "inside";
    EXPECT_FLOAT_EQ(got.more[0], e.unrounded) << "unrounded inside";
    // The patch constant array's elements, at TEXCOORD1 and TEXCOORD2 on both sides.
    EXPECT_EQ(got.more[1], 11.0f);
    EXPECT_EQ(got.more[2], 12.0f);
    EXPECT_EQ(got.more[3], 13.0f);
}

INSTANTIATE_TEST_SUITE_P(
    Partitionings, TessFactorsTest,
    ::testing::Values(Case{"integer", Partitioning::Integer, "ProcessTriTessFactorsAvg", Op::Avg, {2.2f, 3.7f, 5.1f}, 0.5f},
                      Case{"integer", Partitioning::Integer, "ProcessTriTessFactorsMin", Op::Min, {0.5f, 3.7f, 70.0f}, 2.0f},
                      Case{"pow2", Partitioning::Pow2, "ProcessTriTessFactorsMax", Op::Max, {2.2f, 4.0f, 5.1f}, 1.0f},
                      Case{"fractional_odd", Partitioning::FractionalOdd, "ProcessTriTessFactorsMin", Op::Min, {2.2f, 3.7f, 5.1f}, 0.5f},
                      Case{"fractional_odd", Partitioning::FractionalOdd, "ProcessTriTessFactorsMax", Op::Max, {2.2f, 9.5f, 70.0f}, 0.25f},
                      Case{"fractional_even", Partitioning::FractionalEven, "ProcessTriTessFactorsAvg", Op::Avg, {0.5f, 3.7f, 70.0f}, 2.0f}),
    [](const ::testing::TestParamInfo<Case>& param) {
        return std::string(param.param.partitioning) + "_" + std::string(param.param.intrinsic).substr(21);
    });

}  // namespace
}  // namespace d3d11test
