// D3DCompile, its error blob, D3DReflect (cbuffer variables at D3D's packed offsets, computed here
// by hand from D3D's rules; bound resources with their registers; the input signature), and the
// shader/input-layout checks of CreateVertexShader, CreatePixelShader and CreateInputLayout.
#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* kPacking = R"(
cbuffer Packing : register(b2)
{
    float3 a;              // 0: 12 bytes
    float b;               // 12: fits the rest of register 0
    float2 c;              // 16
    float3 d;              // 24 + 12 > 32: next register, 32
    float4x4 m;            // matrices start a register: 48, 64 bytes
    float e;               // 112
    float arr[3];          // arrays start a register: 128; 2 * 16 + 4 = 36 bytes
    float4 f;              // 164 + 16 would straddle: 176
    row_major float3x4 r;  // 192: 3 registers of 4, 48 bytes
    float3x3 n;            // 240: column_major, 3 registers of 3: 2 * 16 + 12 = 44 bytes
    float4 g;              // 284 + 16 would straddle: 288
};
struct VSIn { float3 pos : POSITION; float2 uv : TEXCOORD0; float3 normal : NORMAL; };
float4 VS(VSIn v) : SV_Position
{
    float s = a.x + b + c.x + d.x + m[0][0] + e + arr[2] + f.y + r[2][3] + n[2][2] + g.w + v.uv.x + v.normal.y;
    return float4(v.pos, s);
}
)";

// D3D packs `f` into the tail of the array's last register (36), which GLSL's std140 cannot
// declare: fxport's GL block is then an array of registers, read at D3D's offsets
// (d3d11_cbuffer_packing_test.cpp draws with such blocks).
const char* kTails = R"(
cbuffer Tails
{
    float arr[3];  // 0, 36 bytes
    float2 f;      // D3D: 36
};
float4 VS(float3 pos : POSITION) : SV_Position { return float4(pos, arr[2] + f.y); }
)";

struct Expected {
    const char* name;
    UINT offset, size;
};

TEST(D3D11Shaders, ReflectionGivesD3DPackedOffsetsRegistersAndSignature) {
    Device d;
    ComPtr<ID3DBlob> vs = compile(kPacking, "VS", "vs_5_0", "packing.hlsl");
    ASSERT_TRUE(vs);
    ComPtr<ID3D11ShaderReflection> r;
    ASSERT_EQ(D3DReflect(vs->GetBufferPointer(), vs->GetBufferSize(), r.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_DESC desc;
    ASSERT_EQ(r->GetDesc(&desc), S_OK);
    EXPECT_EQ(desc.Version, (1u << 16) | (5u << 4));  // D3D11_SHVER_VERTEX_SHADER, 5.0
    EXPECT_EQ(desc.ConstantBuffers, 1u);
    EXPECT_EQ(desc.InputParameters, 3u);

    ID3D11ShaderReflectionConstantBuffer* cb = r->GetConstantBufferByName("Packing");
    D3D11_SHADER_BUFFER_DESC cbDesc;
    ASSERT_EQ(cb->GetDesc(&cbDesc), S_OK);
    EXPECT_EQ(cbDesc.Variables, 11u);
    EXPECT_EQ(cbDesc.Size, 304u);  // 288 + 16
    const Expected expected[] = {{"a", 0, 12},    {"b", 12, 4},    {"c", 16, 8},   {"d", 32, 12},  {"m", 48, 64}, {"e", 112, 4},
                                 {"arr", 128, 36}, {"f", 176, 16}, {"r", 192, 48}, {"n", 240, 44}, {"g", 288, 16}};
    for (const Expected& e : expected) {
        D3D11_SHADER_VARIABLE_DESC v;
        ASSERT_EQ(cb->GetVariableByName(e.name)->GetDesc(&v), S_OK) << e.name;
        EXPECT_EQ(v.StartOffset, e.offset) << e.name;
        EXPECT_EQ(v.Size, e.size) << e.name;
    }
    D3D11_SHADER_TYPE_DESC type;
    ASSERT_EQ(cb->GetVariableByName("r")->GetType()->GetDesc(&type), S_OK);
    EXPECT_EQ(type.Class, D3D_SVC_MATRIX_ROWS);
    EXPECT_EQ(type.Rows, 3u);
    EXPECT_EQ(type.Columns, 4u);
    ASSERT_EQ(cb->GetVariableByName("n")->GetType()->GetDesc(&type), S_OK);
    EXPECT_EQ(type.Class, D3D_SVC_MATRIX_COLUMNS);
    D3D11_SHADER_VARIABLE_DESC missing;
    EXPECT_EQ(cb->GetVariableByName("nope")->GetDesc(&missing), E_FAIL);

    D3D11_SHADER_INPUT_BIND_DESC bind;
    ASSERT_EQ(r->GetResourceBindingDescByName("Packing", &bind), S_OK);
    EXPECT_EQ(bind.Type, D3D_SIT_CBUFFER);
    EXPECT_EQ(bind.BindPoint, 2u);  // register(b2)

    // The input signature: semantics by name and index.
    std::vector<std::pair<std::string, UINT>> inputs;
    for (UINT i = 0; i < desc.InputParameters; ++i) {
        D3D11_SIGNATURE_PARAMETER_DESC p;
        ASSERT_EQ(r->GetInputParameterDesc(i, &p), S_OK);
        inputs.emplace_back(p.SemanticName, p.SemanticIndex);
    }
    std::sort(inputs.begin(), inputs.end());
    EXPECT_EQ(inputs, (std::vector<std::pair<std::string, UINT>>{{"NORMAL", 0}, {"POSITION", 0}, {"TEXCOORD", 0}}));

    // The same blob makes a vertex shader (its GL layout agrees with D3D's packing) but no pixel shader.
    ComPtr<ID3D11VertexShader> shader;
    EXPECT_EQ(d.device->CreateVertexShader(vs->GetBufferPointer(), vs->GetBufferSize(), nullptr, shader.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11PixelShader> pixel;
    EXPECT_EQ(d.device->CreatePixelShader(vs->GetBufferPointer(), vs->GetBufferSize(), nullptr, pixel.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("vs_5_0 shader, not a pixel shader"), std::string::npos) << lastError();
}

TEST(D3D11Shaders, VariablesInARegisterTailAreReflectedAndTheShaderIsMade) {
    Device d;
    ComPtr<ID3DBlob> vs = compile(kTails, "VS", "vs_4_0", "tails.hlsl");
    ASSERT_TRUE(vs);
    ComPtr<ID3D11ShaderReflection> r;
    ASSERT_EQ(D3DReflect(vs->GetBufferPointer(), vs->GetBufferSize(), r.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_VARIABLE_DESC v;
    ASSERT_EQ(r->GetVariableByName("f")->GetDesc(&v), S_OK);
    EXPECT_EQ(v.StartOffset, 36u);
    ComPtr<ID3D11VertexShader> shader;
    EXPECT_EQ(d.device->CreateVertexShader(vs->GetBufferPointer(), vs->GetBufferSize(), nullptr, shader.GetAddressOf()), S_OK) << lastError();
    EXPECT_TRUE(shader);
}

TEST(D3D11Shaders, CompileErrorsComeBackInTheErrorBlobWithFileAndLine) {
    const std::string source = "float4 PS() : SV_Target\n{\n    return undeclared;\n}\n";
    ComPtr<ID3DBlob> code, errors;
    EXPECT_EQ(D3DCompile(source.data(), source.size(), "broken.hlsl", nullptr, nullptr, "PS", "ps_4_0", 0, 0, code.GetAddressOf(),
                         errors.GetAddressOf()),
              E_FAIL);
    EXPECT_FALSE(code);
    ASSERT_TRUE(errors);
    const std::string text(static_cast<const char*>(errors->GetBufferPointer()), errors->GetBufferSize());
    EXPECT_NE(text.find("broken.hlsl(3"), std::string::npos) << text;
    EXPECT_NE(text.find("undeclared"), std::string::npos) << text;
    // A missing entry point names the option.
    EXPECT_EQ(D3DCompile(source.data(), source.size(), "broken.hlsl", nullptr, nullptr, "Main", "ps_4_0", 0, 0, code.GetAddressOf(),
                         errors.GetAddressOf()),
              E_FAIL);
    // Not bytecode fxport made.
    Device d;
    const char garbage[] = "DXBC\x01\x02\x03";
    ComPtr<ID3D11PixelShader> ps;
    EXPECT_EQ(d.device->CreatePixelShader(garbage, sizeof garbage, nullptr, ps.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("DXBC"), std::string::npos) << lastError();
}

TEST(D3D11Shaders, DefinesReachTheSource) {
    const std::string source = "float4 PS() : SV_Target { return float4(VALUE, 0, 0, 1); }\n";
    D3D_SHADER_MACRO defines[] = {{"VALUE", "0.5"}, {nullptr, nullptr}};
    ComPtr<ID3DBlob> code, errors;
    EXPECT_EQ(D3DCompile(source.data(), source.size(), "defines.hlsl", defines, nullptr, "PS", "ps_4_0", 0, 0, code.GetAddressOf(),
                         errors.GetAddressOf()),
              S_OK)
        << lastError();
}

TEST(D3D11Shaders, InputLayoutMatchesTheSignatureByNameAndIndex) {
    Device d;
    ComPtr<ID3DBlob> vs = compile(kPacking, "VS", "vs_5_0", "packing.hlsl");
    ASSERT_TRUE(vs);
    D3D11_INPUT_ELEMENT_DESC layout[] = {
        {"POSITION", 0, DXGI_FORMAT_R32G32B32_FLOAT, 0, 0, D3D11_INPUT_PER_VERTEX_DATA, 0},
        {"texcoord", 0, DXGI_FORMAT_R32G32_FLOAT, 0, D3D11_APPEND_ALIGNED_ELEMENT, D3D11_INPUT_PER_VERTEX_DATA, 0},
        {"NORMAL", 0, DXGI_FORMAT_R32G32B32_FLOAT, 0, D3D11_APPEND_ALIGNED_ELEMENT, D3D11_INPUT_PER_VERTEX_DATA, 0},
    };
    ComPtr<ID3D11InputLayout> il;
    EXPECT_EQ(d.device->CreateInputLayout(layout, 3, vs->GetBufferPointer(), vs->GetBufferSize(), il.GetAddressOf()), S_OK) << lastError();
    // TEXCOORD1 is not the shader's TEXCOORD0.
    layout[1].SemanticIndex = 1;
    EXPECT_EQ(d.device->CreateInputLayout(layout, 3, vs->GetBufferPointer(), vs->GetBufferSize(), il.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("TEXCOORD0 has no element"), std::string::npos) << lastError();
    layout[1].SemanticIndex = 0;
    layout[2].Format = DXGI_FORMAT_UNKNOWN;
    EXPECT_EQ(d.device->CreateInputLayout(layout, 3, vs->GetBufferPointer(), vs->GetBufferSize(), il.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("pInputElementDescs[2].Format = DXGI_FORMAT_UNKNOWN"), std::string::npos) << lastError();
    layout[2].Format = DXGI_FORMAT_R32G32B32_FLOAT;
    layout[2].AlignedByteOffset = 6;
    EXPECT_EQ(d.device->CreateInputLayout(layout, 3, vs->GetBufferPointer(), vs->GetBufferSize(), il.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("AlignedByteOffset = 6"), std::string::npos) << lastError();
}

TEST(D3D11Shaders, AnSVPositionInputTakesAnSVPositionElement) {
    Device d;
    const char* source = "float4 VS(float4 p : SV_Position, float2 uv : TEXCOORD0) : SV_Position { return p + uv.x; }\n";
    ComPtr<ID3DBlob> vs = compile(source, "VS", "vs_4_0", "svposition.hlsl");
    ASSERT_TRUE(vs);
    D3D11_INPUT_ELEMENT_DESC layout[] = {
        {"SV_POSITION", 0, DXGI_FORMAT_R32G32B32A32_FLOAT, 0, 0, D3D11_INPUT_PER_VERTEX_DATA, 0},
        {"TEXCOORD", 0, DXGI_FORMAT_R32G32_FLOAT, 0, D3D11_APPEND_ALIGNED_ELEMENT, D3D11_INPUT_PER_VERTEX_DATA, 0},
    };
    ComPtr<ID3D11InputLayout> il;
    EXPECT_EQ(d.device->CreateInputLayout(layout, 2, vs->GetBufferPointer(), vs->GetBufferSize(), il.GetAddressOf()), S_OK) << lastError();
    EXPECT_EQ(d.device->CreateInputLayout(layout + 1, 1, vs->GetBufferPointer(), vs->GetBufferSize(), il.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("SV_POSITION"), std::string::npos) << lastError();
}

TEST(D3D11Shaders, StageShadersTakeOnlyTheirStagesBytecode) {
    Device d;
    ComPtr<ID3DBlob> vs = compile("float4 VS(float4 p : POSITION) : SV_Position { return p; }\n", "VS", "vs_5_0", "stage.hlsl");
    ASSERT_TRUE(vs);
    ComPtr<ID3D11ComputeShader> cs;
    EXPECT_EQ(d.device->CreateComputeShader(vs->GetBufferPointer(), vs->GetBufferSize(), nullptr, cs.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("not a compute shader"), std::string::npos) << lastError();
    ComPtr<ID3D11HullShader> hs;
    EXPECT_EQ(d.device->CreateHullShader(vs->GetBufferPointer(), vs->GetBufferSize(), nullptr, hs.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("not a hull shader"), std::string::npos) << lastError();
    ComPtr<ID3D11DomainShader> ds;
    EXPECT_EQ(d.device->CreateDomainShader(nullptr, 0, nullptr, ds.GetAddressOf()), E_INVALIDARG);
    ComPtr<ID3D11GeometryShader> gs;
    EXPECT_EQ(d.device->CreateGeometryShader(vs->GetBufferPointer(), vs->GetBufferSize(), nullptr, gs.GetAddressOf()), E_INVALIDARG);
    EXPECT_NE(lastError().find("not a geometry shader"), std::string::npos) << lastError();
    ComPtr<ID3D11UnorderedAccessView> uav;
    EXPECT_EQ(d.device->CreateUnorderedAccessView(nullptr, nullptr, uav.GetAddressOf()), E_INVALIDARG);
    d.context->Dispatch(1, 1, 1);
    EXPECT_NE(lastError().find("no compute shader set (CSSetShader)"), std::string::npos) << lastError();
}

}  // namespace
}  // namespace d3d11test
