// Vertex inputs and stage outputs matched by semantic, as D3D matches them: an input layout's
// elements feed the vertex-shader inputs of the same name and index whatever the name (CORNER,
// CELL3, "Delta" for DELTA0 ...), in UINT/SINT/UNORM/FLOAT formats (an int input reads integers
// exactly; an int input fed a FLOAT element reads its bits), checked value by value against the
// CPU's numbers; bad layouts answered with the field and value; a vertex and pixel shader compiled
// apart link by semantic whatever order and subset the pixel shader reads.
#include <algorithm>
#include <cstring>
#include <iterator>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* kAnyNames = R"(
struct VSIn {
    float2 corner : CORNER;
    uint2 cell : CELL3;
    int4 delta : Delta;
    uint4 bytes : PACKED;
    int bits : FLOATBITS;
    float2 scale : TEXCOORD5;
    float weight : WEIGHT;
};
struct VSOut {
    float4 position : SV_Position;
    nointerpolation float4 a : RESULT;
    nointerpolation float4 b : SECOND;
};
VSOut VS(VSIn v)
{
    VSOut o;
    o.position = float4(v.corner, 0, 1);
    o.a = float4(v.cell.x, v.cell.y, v.delta.x, v.delta.w);
    o.b = float4(v.bytes.z, v.weight, asfloat(v.bits) * v.scale.x, v.scale.y);
    return o;
}
struct PSOut { float4 a : SV_Target0; float4 b : SV_Target1; };
PSOut PS(VSOut i) { PSOut o; o.a = i.a; o.b = i.b; return o; }
)";

constexpr UINT kSize = 4;

// One instance's record of slot 1, laid out as the layout below reads it (APPEND_ALIGNED).
struct Record {
    std::uint32_t cell[2];
    std::int32_t delta[4];
    std::uint8_t bytes[4];
    float bits;
    float scale[2];
    std::uint16_t weight[2];  // R16_UNORM, then two bytes of padding
};
static_assert(sizeof(Record) == 44);

const D3D11_INPUT_ELEMENT_DESC kAnyLayout[] = {
    {"corner", 0, DXGI_FORMAT_R32G32_FLOAT, 0, 0, D3D11_INPUT_PER_VERTEX_DATA, 0},
    {"CELL", 3, DXGI_FORMAT_R32G32_UINT, 1, 0, D3D11_INPUT_PER_INSTANCE_DATA, 1},
    {"DELTA", 0, DXGI_FORMAT_R32G32B32A32_SINT, 1, D3D11_APPEND_ALIGNED_ELEMENT, D3D11_INPUT_PER_INSTANCE_DATA, 1},
    {"Packed", 0, DXGI_FORMAT_R8G8B8A8_UINT, 1, D3D11_APPEND_ALIGNED_ELEMENT, D3D11_INPUT_PER_INSTANCE_DATA, 1},
    {"FLOATBITS", 0, DXGI_FORMAT_R32_FLOAT, 1, D3D11_APPEND_ALIGNED_ELEMENT, D3D11_INPUT_PER_INSTANCE_DATA, 1},
    {"TEXCOORD", 5, DXGI_FORMAT_R32G32_FLOAT, 1, D3D11_APPEND_ALIGNED_ELEMENT, D3D11_INPUT_PER_INSTANCE_DATA, 1},
    {"WEIGHT", 0, DXGI_FORMAT_R16_UNORM, 1, D3D11_APPEND_ALIGNED_ELEMENT, D3D11_INPUT_PER_INSTANCE_DATA, 1},
};

ComPtr<ID3D11Texture2D> floatTarget(Device& d) {
    D3D11_TEXTURE2D_DESC desc;
    desc.Width = desc.Height = kSize;
    desc.MipLevels = 1;
    desc.ArraySize = 1;
    desc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    desc.BindFlags = D3D11_BIND_RENDER_TARGET;
    ComPtr<ID3D11Texture2D> t;
    EXPECT_EQ(d.device->CreateTexture2D(&desc, nullptr, t.GetAddressOf()), S_OK) << lastError();
    return t;
}

struct SemanticsTest : ::testing::Test {
    Device d;
    ComPtr<ID3DBlob> vsCode;
    ComPtr<ID3D11VertexShader> vs;
    ComPtr<ID3D11PixelShader> ps;

    void SetUp() override {
        vsCode = compile(kAnyNames, "VS", "vs_5_0", "any_names.hlsl");
        ComPtr<ID3DBlob> psCode = compile(kAnyNames, "PS", "ps_5_0", "any_names.hlsl");
        ASSERT_TRUE(vsCode && psCode);
        ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
        ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
    }
    HRESULT layout(const D3D11_INPUT_ELEMENT_DESC* elements, UINT count, ID3D11InputLayout** out) {
        return d.device->CreateInputLayout(elements, count, vsCode->GetBufferPointer(), vsCode->GetBufferSize(), out);
    }
    ComPtr<ID3D11Buffer> vertexBuffer(const void* data, UINT bytes) {
        D3D11_BUFFER_DESC desc;
        desc.ByteWidth = bytes;
        desc.BindFlags = D3D11_BIND_VERTEX_BUFFER;
        D3D11_SUBRESOURCE_DATA init;
        init.pSysMem = data;
        ComPtr<ID3D11Buffer> b;
        EXPECT_EQ(d.device->CreateBuffer(&desc, &init, b.GetAddressOf()), S_OK) << lastError();
        return b;
    }
};

TEST_F(SemanticsTest, AnySemanticNameAndIntegerFormatsFeedTheirInputs) {
    ComPtr<ID3D11InputLayout> il;
    ASSERT_EQ(layout(kAnyLayout, UINT(std::size(kAnyLayout)), il.GetAddressOf()), S_OK) << lastError();
    const float corners[8] = {-1, 1, 1, 1, -1, -1, 1, -1};  // a strip over the whole target
    Record r{};
    r.cell[0] = 16777215u;  // 2^24 - 1: exact as a float, not through a normalised or float read
    r.cell[1] = 7;
    r.delta[0] = -123456;
    r.delta[3] = 2000000;
    r.bytes[2] = 200;
    r.bits = 1.5f;
    r.scale[0] = 2;
    r.scale[1] = -3;
    r.weight[0] = 0x8000;
    ComPtr<ID3D11Buffer> vb[2] = {vertexBuffer(corners, sizeof corners), vertexBuffer(&r, sizeof r)};
    ComPtr<ID3D11Texture2D> targets[2] = {floatTarget(d), floatTarget(d)};
    ComPtr<ID3D11RenderTargetView> rtv[2];
    for (int i = 0; i < 2; ++i) ASSERT_EQ(d.device->CreateRenderTargetView(targets[i].Get(), nullptr, rtv[i].GetAddressOf()), S_OK) << lastError();
    ID3D11RenderTargetView* const views[2] = {rtv[0].Get(), rtv[1].Get()};
    d.context->OMSetRenderTargets(2, views, nullptr);
    D3D11_VIEWPORT vp;
    vp.Width = vp.Height = kSize;
    d.context->RSSetViewports(1, &vp);
    d.context->IASetInputLayout(il.Get());
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLESTRIP);
    ID3D11Buffer* const buffers[2] = {vb[0].Get(), vb[1].Get()};
    const UINT strides[2] = {8, sizeof(Record)}, offsets[2] = {0, 0};
    d.context->IASetVertexBuffers(0, 2, buffers, strides, offsets);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    d.context->PSSetShader(ps.Get(), nullptr, 0);
    d.context->DrawInstanced(4, 1, 0, 0);
    ASSERT_EQ(lastError(), "");

    const std::array<float, 4> a = {16777215.0f, 7.0f, -123456.0f, 2000000.0f};
    const std::array<float, 4> b = {200.0f, 32768.0f / 65535.0f, 1.5f * 2.0f, -3.0f};
    const std::vector<std::array<float, 4>> gotA = readTexels<std::array<float, 4>>(d, targets[0].Get()), gotB = readTexels<std::array<float, 4>>(d, targets[1].Get());
    for (std::size_t p = 0; p < gotA.size(); ++p) {
        EXPECT_EQ(gotA[p], a) << "pixel " << p;
        for (int c = 0; c < 4; ++c) EXPECT_NEAR(gotB[p][std::size_t(c)], b[std::size_t(c)], 1e-6) << "pixel " << p << " channel " << c;
    }
}

TEST_F(SemanticsTest, BadLayoutsNameTheFieldAndValue) {
    auto rejected = [&](HRESULT code, std::vector<D3D11_INPUT_ELEMENT_DESC> elements, const std::string& words) {
        ComPtr<ID3D11InputLayout> il;
        EXPECT_EQ(layout(elements.data(), UINT(elements.size()), il.GetAddressOf()), code) << words;
        EXPECT_NE(lastError().find(words), std::string::npos) << lastError();
    };
    std::vector<D3D11_INPUT_ELEMENT_DESC> all(std::begin(kAnyLayout), std::end(kAnyLayout));
    std::vector<D3D11_INPUT_ELEMENT_DESC> twice = all;
    twice.push_back({"cell", 3, DXGI_FORMAT_R32G32_UINT, 2, 0, D3D11_INPUT_PER_VERTEX_DATA, 0});  // names match case-insensitively
    rejected(E_INVALIDARG, twice, "pInputElementDescs[7].SemanticName/SemanticIndex = \"cell\"/3 appears twice");
    std::vector<D3D11_INPUT_ELEMENT_DESC> empty = all;
    empty[2].SemanticName = "";
    rejected(E_INVALIDARG, empty, "pInputElementDescs[2].SemanticName is null or empty");
    std::vector<D3D11_INPUT_ELEMENT_DESC> missing(all.begin(), all.end() - 1);
    rejected(E_INVALIDARG, missing, "the vertex shader's input WEIGHT0 has no element in the layout");
    std::vector<D3D11_INPUT_ELEMENT_DESC> otherIndex = all;
    otherIndex[1].SemanticIndex = 2;  // CELL2 feeds nothing, CELL3 is fed by nothing
    rejected(E_INVALIDARG, otherIndex, "the vertex shader's input CELL3 has no element in the layout");
    std::vector<D3D11_INPUT_ELEMENT_DESC> unaligned = all;
    unaligned[6].AlignedByteOffset = 41;  // R16_UNORM: 2-byte components
    rejected(E_INVALIDARG, unaligned, "pInputElementDescs[6].AlignedByteOffset = 41 (must be a multiple of 2, the format's component size)");
    std::vector<D3D11_INPUT_ELEMENT_DESC> packedUint = all;
    packedUint[3].Format = DXGI_FORMAT_R10G10B10A2_UINT;  // GL has no integer attribute of packed components
    rejected(E_NOTIMPL, packedUint, "pInputElementDescs[3].Format = DXGI_FORMAT_R10G10B10A2_UINT (25)");
}

// A vertex shader and pixel shaders compiled apart (each its own D3DCompile): the pixel shaders
// read a subset of the outputs, in other orders and with fewer components, by semantic.
const char* kWriter = R"(
struct VSOut {
    float4 position : SV_Position;
    float3 alpha : ALPHA;
    float2 beta : BETA;
    float4 gamma : GAMMA;
    float delta : TEXCOORD2;
    nointerpolation uint cell : CELL;
    float4 world : POSITION0;  // from SM4 a user semantic beside SV_Position (NvCloth, FaceWorks)
};
VSOut VS(uint id : SV_VertexID)
{
    VSOut o;
    o.position = float4(id == 1 ? 3.0 : -1.0, id == 2 ? -3.0 : 1.0, 0, 1);
    o.alpha = float3(1, 2, 3);
    o.beta = float2(4, 5);
    o.gamma = float4(6, 7, 8, 9);
    o.delta = 10;
    o.cell = 11;
    o.world = float4(12, 13, 14, 15);
    return o;
}
)";

const char* kReaders[] = {
    // The same order, all of it.
    R"(float4 PS(float4 p : SV_Position, float3 a : ALPHA, float2 b : BETA, float4 g : GAMMA, float d : TEXCOORD2,
                 nointerpolation uint c : CELL) : SV_Target { return float4(a.x + b.y, g.w, d, c); })",
    // A subset, another order, fewer components, no SV_Position.
    R"(float4 PS(nointerpolation uint c : CELL, float2 g : GAMMA, float d : TEXCOORD2, float2 b : BETA) : SV_Target
       { return float4(g.y, b.x, d, c); })",
    // One user semantic only, declared in a struct.
    R"(struct In { float4 p : SV_Position; float4 g : GAMMA; };
       float4 PS(In i) : SV_Target { return i.g; })",
    // POSITION0 is the varying the vertex shader wrote there, not the pixel's position.
    R"(float4 PS(float4 p : SV_Position, float4 w : POSITION0) : SV_Target { return w; })",
};
const std::array<float, 4> kRead[] = {{6, 9, 10, 11}, {7, 4, 10, 11}, {6, 7, 8, 9}, {12, 13, 14, 15}};

TEST(D3D11StageLinks, ShadersCompiledApartLinkBySemantic) {
    Device d;
    ComPtr<ID3DBlob> vsCode = compile(kWriter, "VS", "vs_5_0", "writer.hlsl");
    ASSERT_TRUE(vsCode);
    ComPtr<ID3D11VertexShader> vs;
    ASSERT_EQ(d.device->CreateVertexShader(vsCode->GetBufferPointer(), vsCode->GetBufferSize(), nullptr, vs.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11Texture2D> target = floatTarget(d);
    ComPtr<ID3D11RenderTargetView> rtv;
    ASSERT_EQ(d.device->CreateRenderTargetView(target.Get(), nullptr, rtv.GetAddressOf()), S_OK) << lastError();
    d.context->OMSetRenderTargets(1, rtv.GetAddressOfConst(), nullptr);
    D3D11_VIEWPORT vp;
    vp.Width = vp.Height = kSize;
    d.context->RSSetViewports(1, &vp);
    d.context->IASetPrimitiveTopology(D3D11_PRIMITIVE_TOPOLOGY_TRIANGLELIST);
    d.context->VSSetShader(vs.Get(), nullptr, 0);
    for (std::size_t r = 0; r < std::size(kReaders); ++r) {
        ComPtr<ID3DBlob> psCode = compile(kReaders[r], "PS", "ps_5_0", "reader.hlsl");
        ASSERT_TRUE(psCode);
        ComPtr<ID3D11PixelShader> ps;
        ASSERT_EQ(d.device->CreatePixelShader(psCode->GetBufferPointer(), psCode->GetBufferSize(), nullptr, ps.GetAddressOf()), S_OK) << lastError();
        const FLOAT clear[4] = {-1, -1, -1, -1};
        d.context->ClearRenderTargetView(rtv.Get(), clear);
        d.context->PSSetShader(ps.Get(), nullptr, 0);
        d.context->Draw(3, 0);
        ASSERT_EQ(lastError(), "") << "reader " << r;
        for (const std::array<float, 4>& t : readTexels<std::array<float, 4>>(d, target.Get())) ASSERT_EQ(t, kRead[r]) << "reader " << r;
    }
}

// The output signatures reflection reports: the vertex shader's position and user semantics, the
// pixel shader's targets.
TEST(D3D11StageLinks, ReflectionListsEachStageOutputs) {
    auto outputsOf = [](ID3DBlob* code) {
        std::vector<std::string> out;
        ComPtr<ID3D11ShaderReflection> r;
        EXPECT_EQ(D3DReflect(code->GetBufferPointer(), code->GetBufferSize(), r.GetAddressOf()), S_OK) << lastError();
        if (!r) return out;
        D3D11_SHADER_DESC desc;
        EXPECT_EQ(r->GetDesc(&desc), S_OK);
        for (UINT i = 0; i < desc.OutputParameters; ++i) {
            D3D11_SIGNATURE_PARAMETER_DESC p;
            EXPECT_EQ(r->GetOutputParameterDesc(i, &p), S_OK);
            out.push_back(std::string(p.SemanticName) + std::to_string(p.SemanticIndex) + (p.SystemValueType != D3D_NAME_UNDEFINED ? " sv" : ""));
        }
        D3D11_SIGNATURE_PARAMETER_DESC p;
        EXPECT_EQ(r->GetOutputParameterDesc(desc.OutputParameters, &p), E_INVALIDARG);
        EXPECT_NE(lastError().find("GetOutputParameterDesc: index"), std::string::npos) << lastError();
        return out;
    };
    ComPtr<ID3DBlob> vs = compile(kWriter, "VS", "vs_5_0", "writer.hlsl"), ps = compile(kAnyNames, "PS", "ps_5_0", "any_names.hlsl");
    ASSERT_TRUE(vs && ps);
    std::vector<std::string> written = outputsOf(vs.Get());
    std::sort(written.begin() + 1, written.end());
    EXPECT_EQ(written, (std::vector<std::string>{"SV_Position0 sv", "ALPHA0", "BETA0", "CELL0", "GAMMA0", "POSITION0", "TEXCOORD2"}));
    EXPECT_EQ(outputsOf(ps.Get()), (std::vector<std::string>{"SV_Target0 sv", "SV_Target1 sv"}));
}

}  // namespace
}  // namespace d3d11test
