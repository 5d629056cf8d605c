// The compute, geometry, hull and domain stages of the D3D11 front end, written as D3D11 code
// writes them and checked against a CPU computation of the same math:
//   - a compute shader filling a RWStructuredBuffer of structs from a StructuredBuffer, a second
//     dispatch summing the first one's output through a shader-resource view of it, both read
//     back through a staging buffer (CopyResource, Map READ);
//   - a geometry shader expanding points into pixel-aligned squares (its own constant buffer);
//   - a quad patch tessellated by a hull and a domain shader: the domain shader's (u, v, u*v) at
//     every covered pixel, u*v within the bound only a tessellation factor of 8 reaches;
//   - misuse: a dispatch with an empty UAV slot, a patch list without a hull shader, invalid
//     buffer and view descriptions (E_INVALIDARG / E_NOTIMPL naming the field and value).
#include <cmath>
#include <cstring>
#include <set>

#include "d3d11_test_support.h"
#include "shader_sources/quad_patch_stages.h"

namespace d3d11test {
namespace {



// A render target of `format` and its view, bound with a viewport over all of it.
struct Target {
    ComPtr<ID3D11Texture2D> texture;
    ComPtr<ID3D11RenderTargetView> view;
};
Target bindTarget(Device& d, UINT size, DXGI_FORMAT format) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = size;
    desc.MipLevels = 1;
    desc.ArraySize = 1;
    desc.Format = format;
    desc.BindFlags = D3D11_BIND_RENDER_TARGET;
    Target t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.texture.GetAddressOf()), S_OK) << lastError();
    EXPECT_EQ(d.device->CreateRenderTargetView(t.texture.Get(), nullptr, t.view.GetAddressOf()), S_OK) << lastError();
    const FLOAT clear[4] = {0, 0, 0, 0};
    d.context->ClearRenderTargetView(t.view.Get(), clear);
    d.context->OMSetRenderTargets(1, t.view.GetAddressOfConst(), nullptr);
    D3D11_VIEWPORT vp;
    vp.Width = vp.Height = FLOAT(size);
    d.context->RSSetViewports(1, &vp);
    return t;
}

const char* kCompute = R"(
cbuffer Params : register(b0) { float Scale; uint Count; };
struct Particle { float3 position; float mass; };
StructuredBuffer<float> Input : register(t0);
RWStructuredBuffer<Particle> Particles : register(u0);

[numthreads(64, 1, 1)]
void Expand(uint3 id : SV_DispatchThreadID)
{
    if (id.x >= Count) return;
    float x = Input[id.x];
    Particle p;
    p.position = float3(x, x * x, -x) * Scale;
    p.mass = id.x;
    Particles[id.x] = p;
}

StructuredBuffer<Particle> ParticlesIn : register(t1);
RWStructuredBuffer<float> Sum : register(u1);

[numthreads(1, 1, 1)]
void Total()
{
    float s = 0;
    for (uint i = 0; i < Count; ++i) s += ParticlesIn[i].position.y + ParticlesIn[i].mass;
    Sum[0] = s;
}
)";

struct Particle {
    float position[3];
    float mass;
};

TEST(D3D11Stages, ComputeShaderFillsAStructuredBufferLikeTheCpu) {
    Device d;
    ComPtr<ID3DBlob> expandCode = compile(kCompute, "Expand", "cs_5_0", "compute.hlsl");
    ComPtr<ID3DBlob> totalCode = compile(kCompute, "Total", "cs_5_0", "compute.hlsl");
    ASSERT_TRUE(expandCode && totalCode);
    ComPtr<ID3D11ComputeShader> expand, total;
    ASSERT_EQ(d.device->CreateComputeShader(expandCode->GetBufferPointer(), expandCode->GetBufferSize(), nullptr, expand.GetAddressOf()), S_OK)
        << lastError();
    ASSERT_EQ(d.device->CreateComputeShader(totalCode->GetBufferPointer(), totalCode->GetBufferSize(), nullptr, total.GetAddressOf()), S_OK)
        << lastError();

    const UINT count = 200, capacity = 256;  // not a multiple of the group size: the shader's bound check matters
    std::vector<float> input(count);
    for (UINT i = 0; i < count; ++i) input[i] = 0.25f * float(i) - 7.0f;
    ComPtr<ID3D11Buffer> in = makeBuffer(d, input.data(), count * 4, D3D11_BIND_SHADER_RESOURCE, D3D11_RESOURCE_MISC_BUFFER_STRUCTURED, 4);
    std::vector<Particle> sentinel(capacity, Particle{{-1, -1, -1}, -1});
    ComPtr<ID3D11Buffer> particles = makeBuffer(d, sentinel.data(), capacity * UINT(sizeof(Particle)),
                                                D3D11_BIND_UNORDERED_ACCESS | D3D11_BIND_SHADER_RESOURCE, D3D11_RESOURCE_MISC_BUFFER_STRUCTURED,
                                                sizeof(Particle));
    ComPtr<ID3D11Buffer> sum = makeBuffer(d, nullptr, 4, D3D11_BIND_UNORDERED_ACCESS, D3D11_RESOURCE_MISC_BUFFER_STRUCTURED, 4);
    const struct {
        float scale;
        UINT count;
        float pad[2];
    } params = {1.5f, count, {0, 0}};
    ComPtr<ID3D11Buffer> cb = makeBuffer(d, &params, sizeof params, D3D11_BIND_CONSTANT_BUFFER);

    ComPtr<ID3D11ShaderResourceView> inView, particlesView;
    ASSERT_EQ(d.device->CreateShaderResourceView(in.Get(), nullptr, inView.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_RESOURCE_VIEW_DESC srvDesc;
    srvDesc.ViewDimension = D3D11_SRV_DIMENSION_BUFFER;
    srvDesc.Buffer.FirstElement = 0;
    srvDesc.Buffer.NumElements = capacity;
    ASSERT_EQ(d.device->CreateShaderResourceView(particles.Get(), &srvDesc, particlesView.GetAddressOf()), S_OK) << lastError();
    D3D11_UNORDERED_ACCESS_VIEW_DESC uavDesc;
    uavDesc.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
    uavDesc.Buffer.NumElements = capacity;
    ComPtr<ID3D11UnorderedAccessView> particlesUav, sumUav;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(particles.Get(), &uavDesc, particlesUav.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreateUnorderedAccessView(sum.Get(), nullptr, sumUav.GetAddressOf()), S_OK) << lastError();

    d.context->CSSetShader(expand.Get(), nullptr, 0);
    d.context->CSSetConstantBuffers(0, 1, cb.GetAddressOfConst());
    d.context->CSSetShaderResources(0, 1, inView.GetAddressOfConst());
    d.context->CSSetUnorderedAccessViews(0, 1, particlesUav.GetAddressOfConst(), nullptr);
    d.context->Dispatch((count + 63) / 64, 1, 1);
    ASSERT_EQ(lastError(), "");
    // The second dispatch reads the first one's output through an SRV: D3D orders them.
    ID3D11UnorderedAccessView* const none[1] = {nullptr};
    d.context->CSSetUnorderedAccessViews(0, 1, none, nullptr);
    d.context->CSSetShader(total.Get(), nullptr, 0);
    d.context->CSSetShaderResources(1, 1, particlesView.GetAddressOfConst());
    d.context->CSSetUnorderedAccessViews(1, 1, sumUav.GetAddressOfConst(), nullptr);
    d.context->Dispatch(1, 1, 1);
    ASSERT_EQ(lastError(), "");

    // The reflection: the thread group, and the buffers at their registers with their element size.
    ComPtr<ID3D11ShaderReflection> reflection;
    ASSERT_EQ(D3DReflect(expandCode->GetBufferPointer(), expandCode->GetBufferSize(), reflection.GetAddressOf()), S_OK) << lastError();
    UINT gx = 0, gy = 0, gz = 0;
    EXPECT_EQ(reflection->GetThreadGroupSize(&gx, &gy, &gz), 64u);
    EXPECT_EQ(gx, 64u);
    EXPECT_EQ(gy, 1u);
    D3D11_SHADER_DESC shaderDesc;
    ASSERT_EQ(reflection->GetDesc(&shaderDesc), S_OK);
    EXPECT_EQ(shaderDesc.Version >> 16, 5u);  // D3D11_SHVER_COMPUTE_SHADER
    D3D11_SHADER_INPUT_BIND_DESC bind;
    ASSERT_EQ(reflection->GetResourceBindingDescByName("Particles", &bind), S_OK) << lastError();
    EXPECT_EQ(bind.Type, D3D_SIT_UAV_RWSTRUCTURED);
    EXPECT_EQ(bind.BindPoint, 0u);
    EXPECT_EQ(bind.NumSamples, 16u);
    ASSERT_EQ(reflection->GetResourceBindingDescByName("Input", &bind), S_OK) << lastError();
    EXPECT_EQ(bind.Type, D3D_SIT_STRUCTURED);
    EXPECT_EQ(bind.Dimension, D3D_SRV_DIMENSION_BUFFER);

    std::vector<Particle> got = readBuffer<Particle>(d, particles.Get());
    ASSERT_EQ(got.size(), capacity);
    float cpuSum = 0;
    for (UINT i = 0; i < capacity; ++i) {
        const Particle& p = got[i];
        if (i >= count) {
            EXPECT_EQ(p.mass, -1.0f) << "element " << i << " is past Count and must stay untouched";
            continue;
        }
        const float x = input[i];
        const float expected[3] = {x * 1.5f, x * x * 1.5f, -x * 1.5f};
        for (int c = 0; c < 3; ++c) EXPECT_NEAR(p.position[c], expected[c], std::abs(expected[c]) * 2e-7f + 1e-6f) << "element " << i << "." << c;
        EXPECT_EQ(p.mass, float(i)) << "element " << i;
        cpuSum += expected[1] + float(i);
    }
    EXPECT_NEAR(readBuffer<float>(d, sum.Get())[0], cpuSum, std::abs(cpuSum) * 1e-6f);
}

const char* kPointSprites = R"(
cbuffer Pixels : register(b0) { float2 PixelToNdc; };   // the geometry stage's b0: (2/W, 2/H)
struct Vertex { float2 centre : POSITION; float radius : PSIZE; float4 color : COLOR0; };
// Between the stages: user semantics (a loose-compiled vertex shader writes POSITION and PSIZE
// outputs as gl_Position / point size, which a geometry shader could not read back), and an
// SV_Position the geometry shader ignores (fxport's compiler wants one from every vertex shader).
struct Point { float2 centre : TEXCOORD0; float radius : TEXCOORD1; float4 color : COLOR0; float4 unused : SV_Position; };
struct Corner { float4 position : SV_Position; float4 color : COLOR0; };

Point VS(Vertex v)
{
    Point p;
    p.centre = v.centre;
    p.radius = v.radius;
    p.color = v.color;
    p.unused = float4(0, 0, 0, 1);
    return p;
}

[maxvertexcount(4)]
void GS(point Point p[1], inout TriangleStream<Corner> stream)
{
    const float2 offsets[4] = { float2(-1, -1), float2(1, -1), float2(-1, 1), float2(1, 1) };
    for (int i = 0; i < 4; ++i) {
        float2 pixel = p[0].centre + offsets[i] * p[0].radius;
        Corner c;
        c.position = float4(pixel.x * PixelToNdc.x - 1, 1 - pixel.y * PixelToNdc.y, 0, 1);
        c.color = p[0].color;
        stream.Append(c);
    }
}

float4 PS(Corner c) : SV_Target { return c.color; }
)";

TEST(D3D11Stages, GeometryShaderExpandsPointsIntoSquares) {
    Device d;
    ComPtr<ID3DBlob> vsCode = compile(kPointSprites, "VS", "vs_5_0", "sprites.hlsl");
    ComPtr<ID3DBlob> gsCode = compile(kPointSprites, "GS", "gs_5_0", "sprites.hlsl");
    ComPtr<ID3DBlob> psCode = compile(kPointSprites, "PS", "ps_5_0", "sprites.hlsl");
    ASSERT_TRUE(vsCode && gsCode && psCode);
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11GeometryShader> gs;
    ComPtr<ID3D11PixelShader> ps;
    ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreateGeometryShader(gsCode->GetBufferPointer(), gsCode->GetBufferSize(), nullptr, gs.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
    const D3D11_INPUT_ELEMENT_DESC elements[] = {
        {"POSITION", 0, DXGI_FORMAT_R32G32_FLOAT, 0, 0, D3D11_INPUT_PER_VERTEX_DATA, 0},
        {"PSIZE", 0, DXGI_FORMAT_R32_FLOAT, 0, D3D11_APPEND_ALIGNED_ELEMENT, D3D11_INPUT_PER_VERTEX_DATA, 0},
        {"COLOR", 0, DXGI_FORMAT_R8G8B8A8_UNORM, 0, D3D11_APPEND_ALIGNED_ELEMENT, D3D11_INPUT_PER_VERTEX_DATA, 0},
    };
    ComPtr<ID3D11InputLayout> layout;
    ASSERT_EQ(d.device->CreateInputLayout(elements, 3, vsCode->GetBufferPointer(), vsCode->GetBufferSize(), layout.GetAddressOf()), S_OK)
        << lastError();

    struct Point {
        float x, y, half;
        std::uint32_t rgba;
    };
    // Squares with edges on pixel boundaries: no pixel centre lies on an edge.
    const Point points[3] = {{8, 8, 4, 0xff0000ffu}, {22, 12, 6, 0xff00ff00u}, {12, 26, 2, 0x80ff0000u}};
    const UINT size = 32;
    ComPtr<ID3D11Buffer> vb = makeBuffer(d, points, sizeof points, D3D11_BIND_VERTEX_BUFFER);
    const float pixelToNdc[4] = {2.0f / size, 2.0f / size, 0, 0};
    ComPtr<ID3D11Buffer> cb = makeBuffer(d, pixelToNdc, sizeof pixelToNdc, D3D11_BIND_CONSTANT_BUFFER);
    Target target = bindTarget(d, size, DXGI_FORMAT_R8G8B8A8_UNORM);
    D3D11_RASTERIZER_DESC rd;
    rd.CullMode = D3D11_CULL_NONE;  // a strip's triangles alternate winding
    ComPtr<ID3D11RasterizerState> noCull;
    ASSERT_EQ(d.device->CreateRasterizerState(&rd, noCull.GetAddressOf()), S_OK);
    d.context->RSSetState(noCull.Get());
    d.context->IASetInputLayout(layout.Get());
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_POINTLIST);
    const UINT stride = sizeof(Point), offset = 0;
    d.context->IASetVertexBuffers(0, 1, vb.GetAddressOfConst(), &stride, &offset);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->GSSetShader(gs.Get(), nullptr, 0);
    d.context->GSSetConstantBuffers(0, 1, cb.GetAddressOfConst());
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->Draw(3, 0);
    ASSERT_EQ(lastError(), "");

    std::vector<std::array<std::uint8_t, 4>> pixels = readPixels(d, target.texture.Get());
    for (UINT y = 0; y < size; ++y)
        for (UINT x = 0; x < size; ++x) {
            std::uint32_t expected = 0;  // the clear
            for (const Point& p : points)  // later points draw over earlier ones
                if (x + 0.5f > p.x - p.half && x + 0.5f < p.x + p.half && y + 0.5f > p.y - p.half && y + 0.5f < p.y + p.half) expected = p.rgba;
            const auto& got = pixels[y * size + x];
            const std::uint32_t rgba = got[0] | got[1] << 8 | got[2] << 16 | std::uint32_t(got[3]) << 24;
            EXPECT_EQ(rgba, expected) << "pixel " << x << "," << y;
        }
}

const std::string kTessellation = std::string(R"(
cbuffer Tessellation : register(b0) { float Factor; };   // the hull stage's b0
struct ControlPoint { float3 pos : TEXCOORD0; float4 unused : SV_Position; };   // (see kPointSprites on semantics between stages)
struct PatchConstants { float edges[4] : SV_TessFactor; float inside[2] : SV_InsideTessFactor; };
struct DomainOut { float4 pos : SV_Position; float4 color : COLOR0; };

ControlPoint VS(float3 pos : POSITION) { ControlPoint o; o.pos = pos; o.unused = float4(pos, 1); return o; }

)") + fxport::test::kQuadPatchStages;

struct TessellationTest : ::testing::Test {
    Device d;
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11HullShader> hs;
    ComPtr<ID3D11DomainShader> ds;
    ComPtr<ID3D11PixelShader> ps;
    ComPtr<ID3D11InputLayout> layout;
    ComPtr<ID3D11Buffer> corners, factor;

    void SetUp() override { build(kTessellation, 8); }

    // The four stages of `source` (its entry points VS, HS, DS and PS), the patch's corners and a
    // tessellation factor of `tessFactor` in the hull stage's b0.
    void build(const std::string& source, float tessFactor) {
        ComPtr<ID3DBlob> vsCode = compile(source, "VS", "vs_5_0", "tessellate.hlsl");
        ComPtr<ID3DBlob> hsCode = compile(source, "HS", "hs_5_0", "tessellate.hlsl");
        ComPtr<ID3DBlob> dsCode = compile(source, "DS", "ds_5_0", "tessellate.hlsl");
        ComPtr<ID3DBlob> psCode = compile(source, "PS", "ps_5_0", "tessellate.hlsl");
        ASSERT_TRUE(vsCode && hsCode && dsCode && psCode);
        ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
        ASSERT_EQ(d.device->CreateHullShader(hsCode->GetBufferPointer(), hsCode->GetBufferSize(), nullptr, hs.GetAddressOf()), S_OK) << lastError();
        ASSERT_EQ(d.device->CreateDomainShader(dsCode->GetBufferPointer(), dsCode->GetBufferSize(), nullptr, ds.GetAddressOf()), S_OK) << lastError();
        ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
        const D3D11_INPUT_ELEMENT_DESC element = {"POSITION", 0, DXGI_FORMAT_R32G32B32_FLOAT, 0, 0, D3D11_INPUT_PER_VERTEX_DATA, 0};
        ASSERT_EQ(d.device->CreateInputLayout(&element, 1, vsCode->GetBufferPointer(), vsCode->GetBufferSize(), layout.GetAddressOf()), S_OK)
            << lastError();
        // Control points: top-left, top-right, bottom-right, bottom-left of NDC [-0.5, 0.5]^2.
        const float points[12] = {-0.5f, 0.5f, 0, 0.5f, 0.5f, 0, 0.5f, -0.5f, 0, -0.5f, -0.5f, 0};
        corners = makeBuffer(d, points, sizeof points, D3D11_BIND_VERTEX_BUFFER);
        const float constants[4] = {tessFactor, 0, 0, 0};
        factor = makeBuffer(d, constants, sizeof constants, D3D11_BIND_CONSTANT_BUFFER);
        d.context->IASetInputLayout(layout.Get());
        const UINT stride = 12, offset = 0;
        d.context->IASetVertexBuffers(0, 1, corners.GetAddressOfConst(), &stride, &offset);
        d.context->VSSetShader(vs.Get(), nullptr, 0);
        d.context->PSSetShader(ps.Get(), nullptr, 0);
    }
};

TEST_F(TessellationTest, QuadPatchMatchesTheDomainShaderOnTheCpu) {
    const int size = 64;
    Target target = bindTarget(d, size, DXGI_FORMAT_R32G32B32A32_FLOAT);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_4_CONTROL_POINT_PATCHLIST);
    d.context->HSSetShader(hs.Get(), nullptr, 0);
    d.context->HSSetConstantBuffers(0, 1, factor.GetAddressOfConst());
    d.context->DSSetShader(ds.Get(), nullptr, 0);
    d.context->Draw(4, 0);
    ASSERT_EQ(lastError(), "");

    const std::vector<float> texels = readTexels<float>(d, target.texture.Get(), 4);
    int inside = 0;
    double worstUV = 0, worstProduct = 0;
    for (int py = 0; py < size; ++py)
        for (int px = 0; px < size; ++px) {
            // The pixel centre in NDC (y up, row 0 at the top), then in the patch's (u, v).
            const double x = (px + 0.5) / (size / 2.0) - 1, y = 1 - (py + 0.5) / (size / 2.0);
            const double u = x + 0.5, v = 0.5 - y;
            const float* t = &texels[std::size_t((py * size + px) * 4)];
            const double edge = 1.0 / size;
            if (u < -edge || u > 1 + edge || v < -edge || v > 1 + edge) {
                EXPECT_EQ(t[3], 0.0f) << "pixel " << px << "," << py << " is outside the patch";
                continue;
            }
            if (u < edge || u > 1 - edge || v < edge || v > 1 - edge) continue;
            ++inside;
            EXPECT_EQ(t[3], 1.0f) << "pixel " << px << "," << py << " is inside the patch";
            worstUV = std::max({worstUV, std::abs(t[0] - u), std::abs(t[1] - v)});
            worstProduct = std::max(worstProduct, std::abs(t[2] - u * v));
        }
    EXPECT_EQ(inside, (size / 2) * (size / 2));
    EXPECT_LT(worstUV, 1e-4);
    // u*v is linear inside each tessellated triangle: off by at most du*dv/4 = 1/(4*8*8) with
    // factor 8 (the hull stage's constant buffer); untessellated it would be off by up to 0.25.
    EXPECT_LT(worstProduct, 1.0 / (4 * 8 * 8) + 1e-4);
    EXPECT_GT(worstProduct, 1e-3) << "u*v exact everywhere: the triangles were not interpolating at all?";
}

// [partitioning("pow2")]: D3D rounds each factor up to a power of two (3 tessellates as 4), which
// GL has no spacing for (pow2_partitioning.h). The domain shader passes its location flat, so every
// pixel shows the (u, v) of a generated vertex: all multiples of 1/4, and 1/4 itself among them.
TEST_F(TessellationTest, Pow2PartitioningRoundsTheFactorUpToAPowerOfTwo) {
    std::string source = kTessellation;
    const std::string integer = "[partitioning(\"integer\")]";
    source.replace(source.find(integer), integer.size(), "[partitioning(\"pow2\")]");
    const std::string color = "float4 color : COLOR0;";
    source.replace(source.find(color), color.size(), "nointerpolation float4 color : COLOR0;");
    build(source, 3);
    const int size = 64;
    Target target = bindTarget(d, size, DXGI_FORMAT_R32G32B32A32_FLOAT);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_4_CONTROL_POINT_PATCHLIST);
    d.context->HSSetShader(hs.Get(), nullptr, 0);
    d.context->HSSetConstantBuffers(0, 1, factor.GetAddressOfConst());
    d.context->DSSetShader(ds.Get(), nullptr, 0);
    d.context->Draw(4, 0);
    ASSERT_EQ(lastError(), "");
    const std::vector<float> texels = readTexels<float>(d, target.texture.Get(), 4);
    std::set<float> us;
    for (int i = 0; i < size * size; ++i)
        if (texels[std::size_t(i) * 4 + 3] == 1.0f) us.insert(texels[std::size_t(i) * 4]);
    ASSERT_FALSE(us.empty()) << "nothing was drawn";
    for (float u : us) EXPECT_NEAR(u * 4, std::round(u * 4), 1e-4) << "u = " << u << " is no vertex of 4 segments";
    EXPECT_EQ(us.count(0.25f), 1u) << "no vertex at u = 1/4: fewer than 4 segments";
}

TEST_F(TessellationTest, PatchListsAndHullShadersGoTogether) {
    Target target = bindTarget(d, 8, DXGI_FORMAT_R8G8B8A8_UNORM);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_4_CONTROL_POINT_PATCHLIST);
    d.context->Draw(4, 0);  // no hull or domain shader
    EXPECT_NE(lastError().find("HSSetShader"), std::string::npos) << lastError();
    d.context->HSSetShader(hs.Get(), nullptr, 0);
    d.context->DSSetShader(ds.Get(), nullptr, 0);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->Draw(3, 0);
    EXPECT_NE(lastError().find("CONTROL_POINT_PATCHLIST"), std::string::npos) << lastError();
}

TEST(D3D11Stages, MisuseIsAnsweredWithTheFieldAndValue) {
    Device d;
    auto rejected = [&](HRESULT code, const D3D11_BUFFER_DESC& desc, const std::string& words) {
        ComPtr<ID3D11Buffer> b;
        EXPECT_EQ(d.device->CreateBuffer(&desc, nullptr, b.GetAddressOf()), code) << words;
        EXPECT_NE(lastError().find(words), std::string::npos) << lastError();
    };
    D3D11_BUFFER_DESC desc;
    desc.ByteWidth = 64;
    desc.BindFlags = D3D11_BIND_UNORDERED_ACCESS | D3D11_BIND_SHADER_RESOURCE;
    desc.MiscFlags = D3D11_RESOURCE_MISC_BUFFER_STRUCTURED;
    desc.StructureByteStride = 6;
    rejected(E_INVALIDARG, desc, "StructureByteStride = 6");
    desc.StructureByteStride = 12;
    rejected(E_INVALIDARG, desc, "ByteWidth = 64 is not a multiple of StructureByteStride = 12");
    desc.StructureByteStride = 16;
    desc.Usage = D3D11_USAGE_DYNAMIC;
    desc.CPUAccessFlags = D3D11_CPU_ACCESS_WRITE;
    rejected(E_INVALIDARG, desc, "with BIND_UNORDERED_ACCESS");
    desc.Usage = D3D11_USAGE_DEFAULT;
    desc.CPUAccessFlags = 0;
    desc.BindFlags |= D3D11_BIND_VERTEX_BUFFER;
    rejected(E_INVALIDARG, desc, "cannot be a vertex, index or constant buffer");
    desc.BindFlags = D3D11_BIND_UNORDERED_ACCESS;

    ComPtr<ID3D11Buffer> structured;
    ASSERT_EQ(d.device->CreateBuffer(&desc, nullptr, structured.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11ShaderResourceView> srv;
    EXPECT_EQ(d.device->CreateShaderResourceView(structured.Get(), nullptr, srv.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("lack D3D11_BIND_SHADER_RESOURCE"), std::string::npos) << lastError();
    D3D11_UNORDERED_ACCESS_VIEW_DESC uav;
    uav.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
    uav.Buffer.FirstElement = 1;
    uav.Buffer.NumElements = 4;
    ComPtr<ID3D11UnorderedAccessView> view;
    EXPECT_EQ(d.device->CreateUnorderedAccessView(structured.Get(), &uav, view.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("{FirstElement 1, NumElements 4}: the buffer has 4 elements"), std::string::npos) << lastError();
    uav.Buffer.FirstElement = 0;
    uav.Buffer.NumElements = 5;
    EXPECT_EQ(d.device->CreateUnorderedAccessView(structured.Get(), &uav, view.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("the buffer has 4 elements"), std::string::npos) << lastError();
    uav.Format = DXGI_FORMAT_R32_FLOAT;
    uav.Buffer.NumElements = 4;
    EXPECT_EQ(d.device->CreateUnorderedAccessView(structured.Get(), &uav, view.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("Format = DXGI_FORMAT_R32_FLOAT for a structured buffer"), std::string::npos) << lastError();

    // A dispatch whose UAV slot is empty names the variable and its register; nothing runs.
    ComPtr<ID3DBlob> code = compile(kCompute, "Expand", "cs_5_0", "compute.hlsl");
    ASSERT_TRUE(code);
    ComPtr<ID3D11ComputeShader> cs;
    ASSERT_EQ(d.device->CreateComputeShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, cs.GetAddressOf()), S_OK) << lastError();
    desc.BindFlags = D3D11_BIND_SHADER_RESOURCE;
    desc.StructureByteStride = 4;
    ComPtr<ID3D11Buffer> input;
    ASSERT_EQ(d.device->CreateBuffer(&desc, nullptr, input.GetAddressOf()), S_OK) << lastError();
    ASSERT_EQ(d.device->CreateShaderResourceView(input.Get(), nullptr, srv.GetAddressOf()), S_OK) << lastError();
    d.context->CSSetShader(cs.Get(), nullptr, 0);
    d.context->CSSetShaderResources(0, 1, srv.GetAddressOfConst());
    d.context->Dispatch(1, 1, 1);
    EXPECT_NE(lastError().find("'Particles' (u0), but no unordered-access view is set there"), std::string::npos) << lastError();
    d.context->Dispatch(70000, 1, 1);
    EXPECT_NE(lastError().find("at most 65535"), std::string::npos) << lastError();

    // A view whose StructureByteStride is not the shader's element size (D3D's rule) is refused.
    desc.BindFlags = D3D11_BIND_UNORDERED_ACCESS;
    desc.StructureByteStride = 32;
    ComPtr<ID3D11Buffer> wide;
    ASSERT_EQ(d.device->CreateBuffer(&desc, nullptr, wide.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11UnorderedAccessView> wideView;
    ASSERT_EQ(d.device->CreateUnorderedAccessView(wide.Get(), nullptr, wideView.GetAddressOf()), S_OK) << lastError();
    d.context->CSSetUnorderedAccessViews(0, 1, wideView.GetAddressOfConst(), nullptr);
    d.context->Dispatch(1, 1, 1);
    EXPECT_NE(lastError().find("'Particles' (u0): its elements are 16 bytes, the buffer's StructureByteStride is 32 (D3D11 requires the shader's element size)"),
              std::string::npos)
        << lastError();
}

}  // namespace
}  // namespace d3d11test
