// The constant a shader reads is the one a D3D11 host wrote at the variable's D3D offset. The host
// fills a constant buffer with a distinct value per 4-byte word (word k holds value(k)); the pixel
// shader returns four variables; the expected colour is value(word) at the D3D offsets written out
// here by hand from fxc's packing rules: packoffset, register(cN) on $Globals, a scalar in the tail
// of an array's or a matrix's last register, a float3 after a float, struct members, a member after
// a struct, a dynamically indexed array. D3DReflect must give the same offsets.
#include <cmath>
#include <cstring>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* kVertex = R"(
float4 VS(uint id : SV_VertexID) : SV_Position
{
    float2 p = float2(id == 1 ? 3.0 : -1.0, id == 2 ? -3.0 : 1.0);
    return float4(p, 0.5, 1);
}
)";

// Word k of the constant buffer: a value RGBA8 stores exactly (a multiple of 1/255), distinct for
// the first 250 words.
float valueOf(int word) { return float((word * 37) % 250 + 3) / 255.0f; }

struct Case {
    const char* name;
    const char* source;        // the pixel shader PS, reading constant buffer slot 0
    int words[4];              // D3D word offset of what it returns in r, g, b, a
    std::vector<std::pair<const char*, UINT>> reflected;  // variable -> D3D byte offset
    const char* profile = "ps_4_0";
};

class CbufferPacking : public ::testing::TestWithParam<Case> {};

TEST_P(CbufferPacking, TheShaderReadsTheWordsAtD3DOffsets) {
    const Case& c = GetParam();
    Device d;
    ComPtr<ID3DBlob> vsCode = compile(kVertex, "VS", "vs_4_0", "packing_vs.hlsl");
    ComPtr<ID3DBlob> psCode = compile(c.source, "PS", c.profile, (std::string(c.name) + ".hlsl").c_str());
    ASSERT_TRUE(vsCode && psCode);

    ComPtr<ID3D11ShaderReflection> r;
    ASSERT_EQ(D3DReflect(psCode->GetBufferPointer(), psCode->GetBufferSize(), r.GetAddressOf()), S_OK) << lastError();
    for (const auto& [name, offset] : c.reflected) {
        D3D11_SHADER_VARIABLE_DESC v;
        ASSERT_EQ(r->GetVariableByName(name)->GetDesc(&v), S_OK) << name;
        EXPECT_EQ(v.StartOffset, offset) << name;
    }


    std::vector<float> words(256);
    for (int k = 0; k < int(words.size()); ++k) words[std::size_t(k)] = valueOf(k);
    D3D11_BUFFER_DESC desc;
    desc.ByteWidth = UINT(words.size() * 4);
    desc.BindFlags = D3D11_BIND_CONSTANT_BUFFER;
    D3D11_SUBRESOURCE_DATA data;
    data.pSysMem = words.data();
    ComPtr<ID3D11Buffer> constants;
    ASSERT_EQ(d.device->CreateBuffer(&desc, &data, constants.GetAddressOf()), S_OK) << lastError();
    d.context->PSSetConstantBuffers(0, 1, constants.GetAddressOfConst());

    ComPtr<ID3D11Texture2D> target = drawTriangleToRgba8(d, vsCode.Get(), psCode.Get(), 1, 1);
    ASSERT_EQ(lastError(), "");

    const auto pixel = readPixels(d, target.Get()).at(0);
    for (int ch = 0; ch < 4; ++ch)
        EXPECT_EQ(int(pixel[std::size_t(ch)]), int(std::lround(valueOf(c.words[ch]) * 255.0f)))
            << "channel " << ch << " should be word " << c.words[ch];
}

// Word offsets: byte offset / 4.
const Case kCases[] = {
    {"packoffset_out_of_order",
     "cbuffer C : register(b0) { float4 a : packoffset(c2); float b : packoffset(c0.y); float2 c : packoffset(c1.z); }\n"
     "float4 PS() : SV_Target { return float4(a.w, b, c.x, c.y); }\n",
     {11, 1, 6, 7},
     {{"a", 32}, {"b", 4}, {"c", 24}}},
    {"register_on_globals",
     "float4 g : register(c3);\nfloat k : register(c1);\n"
     "float4 PS() : SV_Target { return float4(g.x, g.z, k, g.y); }\n",
     {12, 14, 4, 13},
     {{"g", 48}, {"k", 16}}},
    {"scalar_after_array",
     "cbuffer C { float a; float b[2]; float c; }\n"
     "float4 PS() : SV_Target { return float4(a, b[0], b[1], c); }\n",
     {0, 4, 8, 9},  // b: c1.x and c2.x; c in b's last register, c2.y
     {{"a", 0}, {"b", 16}, {"c", 36}}},
    {"scalar_after_matrices",
     "cbuffer C { float3x3 m; float s; row_major float2x3 r; float t; }\n"
     "float4 PS() : SV_Target { return float4(m[2][1], s, r[1][2], t); }\n",
     // m: 3 registers of 3 (columns), m[2][1] = column 1 row 2 = word 4 + 2; s = c2.w; r at c3:
     // 2 registers of 3 (rows), r[1][2] = c4.z; t = c4.w.
     {6, 11, 18, 19},
     {{"m", 0}, {"s", 44}, {"r", 48}, {"t", 76}}},
    {"float3_after_float",
     "float x;\nfloat3 y;\nfloat2 z;\nfloat w;\n"
     "float4 PS() : SV_Target { return float4(x, y.z, z.y, w); }\n",
     {0, 3, 5, 6},  // y c0.yzw, z c1.xy, w c1.z
     {{"x", 0}, {"y", 4}, {"z", 16}, {"w", 24}}},
    {"struct_members",
     "struct S { float b; float2 c; };\n"
     "cbuffer C { float a; S p; float d; S q[2]; float e; }\n"
     "float4 PS() : SV_Target { return float4(p.c.y, d, q[1].c.x, e); }\n",
     // p at c1: b c1.x, c c1.yz; d c1.w; q at c2 (stride 16): q[1].c = c3.yz; e c3.w.
     {6, 7, 13, 15},
     {{"a", 0}, {"p", 16}, {"d", 28}, {"q", 32}, {"e", 60}}},
    // Structs holding objects (vkd3d's object-field-offsets, xlate/src/rewrite/
    // uniform_object_structs.h): the objects take no room, but an object array starts a register.
    {"struct_with_objects_in_a_cbuffer",
     "struct M { float2 a; Texture2D t; SamplerState s; float b; Texture2D arr[2]; float c; };\n"
     "cbuffer C { float x; M m; float y; }\n"
     "float4 PS() : SV_Target { return float4(m.a.y, m.b, m.c, y); }\n",
     // m at c1: a c1.xy, b c1.z; arr starts c2, empty: c c2.x; y in m's last register, c2.y.
     {5, 6, 8, 9},
     {{"x", 0}, {"m", 16}, {"y", 36}},
     "ps_5_0"},
    {"struct_with_a_struct_of_objects",
     "struct O { Texture2D t; SamplerState s; };\nstruct N { float a; O o; float b; };\n"
     "N n;\nfloat g;\n"
     "float4 PS() : SV_Target { return float4(n.a, n.b, g, n.a); }\n",
     // n at c0: a c0.x; o starts c1, empty: b c1.x; g c1.y.
     {0, 4, 5, 0},
     {{"n", 0}, {"g", 20}},
     "ps_5_0"},
};

INSTANTIATE_TEST_SUITE_P(D3D11, CbufferPacking, ::testing::ValuesIn(kCases),
                         [](const ::testing::TestParamInfo<Case>& p) { return std::string(p.param.name); });

// arr[i] with i from the buffer: the index picks whole registers (arr's stride is 16), the element
// after the array packs into its last register.
TEST(D3D11CbufferPacking, DynamicIndexReadsWholeRegisters) {
    const char* source =
        "cbuffer C { float4 pad; int i; float arr[3]; float tail; float2x2 m[2]; }\n"
        "float4 PS() : SV_Target { return float4(arr[i], arr[i + 1], tail, m[i][1][i]); }\n";
    // pad c0; i c1.x; arr c2.x c3.x c4.x; tail c4.y; m at c5, 2 registers (columns of 2) each:
    // m[1] at c7, m[1][1][1] = column 1 row 1 = c8.y.
    Device d;
    ComPtr<ID3DBlob> vsCode = compile(kVertex, "VS", "vs_4_0", "dyn_vs.hlsl");
    ComPtr<ID3DBlob> psCode = compile(source, "PS", "ps_4_0", "dyn.hlsl");
    ASSERT_TRUE(vsCode && psCode);
    std::vector<float> words(64);
    for (int k = 0; k < int(words.size()); ++k) words[std::size_t(k)] = valueOf(k);
    const std::int32_t one = 1;
    std::memcpy(&words[4], &one, 4);
    D3D11_BUFFER_DESC desc;
    desc.ByteWidth = UINT(words.size() * 4);
    desc.BindFlags = D3D11_BIND_CONSTANT_BUFFER;
    D3D11_SUBRESOURCE_DATA data;
    data.pSysMem = words.data();
    ComPtr<ID3D11Buffer> constants;
    ASSERT_EQ(d.device->CreateBuffer(&desc, &data, constants.GetAddressOf()), S_OK) << lastError();
    d.context->PSSetConstantBuffers(0, 1, constants.GetAddressOfConst());
    ComPtr<ID3D11Texture2D> target = drawTriangleToRgba8(d, vsCode.Get(), psCode.Get(), 1, 1);
    ASSERT_EQ(lastError(), "");
    const int expected[4] = {12, 16, 17, 33};  // arr[1] c3.x, arr[2] c4.x, tail c4.y, m[1][1][1] c8.y
    const auto pixel = readPixels(d, target.Get()).at(0);
    for (int ch = 0; ch < 4; ++ch)
        EXPECT_EQ(int(pixel[std::size_t(ch)]), int(std::lround(valueOf(expected[ch]) * 255.0f))) << "channel " << ch;
}

}  // namespace
}  // namespace d3d11test
