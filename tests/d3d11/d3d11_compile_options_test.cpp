// D3DCompile's matrix-packing flags and ID3DInclude handlers. The packing test uploads 16 distinct
// floats to a cbuffer and reads a matrix row back through a compute shader: D3D's packing rules say
// which 4 of the 16 a row is (row-major: floats 4r..4r+3; column-major: floats r, r+4, r+8, r+12).
// The include test serves headers from memory and checks the calls D3D documents: Open for each
// #include the preprocessor reaches (not those in skipped #if branches), LOCAL for "x" and SYSTEM
// for <x>, the parent's data for a nested one, one Close per Open, each file closed when the
// preprocessor is done with it (before the next #include of an outer file).
#include <map>
#include <set>

#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

// The float4 compute shader `code` writes to Out[0] (u0), with `constants` at b0.
std::vector<float> computedFloat4(Device& d, ID3DBlob* code, ID3D11Buffer* constants) {
    ComPtr<ID3D11Buffer> results = makeBuffer(d, nullptr, 16, D3D11_BIND_UNORDERED_ACCESS);
    D3D11_UNORDERED_ACCESS_VIEW_DESC uavDesc;
    uavDesc.Format = DXGI_FORMAT_R32G32B32A32_FLOAT;
    uavDesc.ViewDimension = D3D11_UAV_DIMENSION_BUFFER;
    uavDesc.Buffer.NumElements = 1;
    ComPtr<ID3D11UnorderedAccessView> view;
    EXPECT_EQ(d.device->CreateUnorderedAccessView(results.Get(), &uavDesc, view.GetAddressOf()), S_OK) << lastError();
    ComPtr<ID3D11ComputeShader> cs;
    EXPECT_EQ(d.device->CreateComputeShader(code->GetBufferPointer(), code->GetBufferSize(), nullptr, cs.GetAddressOf()), S_OK) << lastError();
    d.context->CSSetShader(cs.Get(), nullptr, 0);
    if (constants) d.context->CSSetConstantBuffers(0, 1, &constants);
    d.context->CSSetUnorderedAccessViews(0, 1, view.GetAddressOfConst(), nullptr);
    d.context->Dispatch(1, 1, 1);
    return readBuffer<float>(d, results.Get());
}

// Row 1 of `m` (declared with `majority`, "" for none) as the compute shader reads it, compiled with `flags`.
std::vector<float> matrixRow(UINT flags, const std::string& prefix, const std::string& majority) {
    Device d;
    float values[16];
    for (int i = 0; i < 16; ++i) values[i] = float(i + 1);
    ComPtr<ID3D11Buffer> constants = makeBuffer(d, values, sizeof values, D3D11_BIND_CONSTANT_BUFFER);
    const std::string source = prefix + "cbuffer C : register(b0) { " + majority + " float4x4 m; };\n"
                               "RWBuffer<float4> Out : register(u0);\n"
                               "[numthreads(1, 1, 1)] void cs() { Out[0] = m[1]; }\n";
    ComPtr<ID3DBlob> code, errors;
    EXPECT_EQ(D3DCompile(source.data(), source.size(), "packing.hlsl", nullptr, nullptr, "cs", "cs_5_0", flags, 0, code.GetAddressOf(),
                         errors.GetAddressOf()),
              S_OK)
        << lastError();
    if (!code) return {};
    return computedFloat4(d, code.Get(), constants.Get());
}

const std::vector<float> kRowMajorRow1 = {5, 6, 7, 8};      // floats 4..7
const std::vector<float> kColumnMajorRow1 = {2, 6, 10, 14};  // floats 1, 5, 9, 13

TEST(D3D11CompileOptions, PackMatrixFlagsSetTheDefaultMajority) {
    EXPECT_EQ(matrixRow(0, "", ""), kColumnMajorRow1);
    EXPECT_EQ(matrixRow(D3DCOMPILE_PACK_MATRIX_ROW_MAJOR, "", ""), kRowMajorRow1);
    EXPECT_EQ(matrixRow(D3DCOMPILE_PACK_MATRIX_COLUMN_MAJOR, "", ""), kColumnMajorRow1);
    // A majority written on the declaration, and a pragma, win over the flag (fxc's /Zpr).
    EXPECT_EQ(matrixRow(D3DCOMPILE_PACK_MATRIX_ROW_MAJOR, "", "column_major"), kColumnMajorRow1);
    EXPECT_EQ(matrixRow(D3DCOMPILE_PACK_MATRIX_ROW_MAJOR, "#pragma pack_matrix(column_major)\n", ""), kColumnMajorRow1);
    EXPECT_EQ(matrixRow(D3DCOMPILE_PACK_MATRIX_COLUMN_MAJOR, "#pragma pack_matrix(row_major)\n", ""), kRowMajorRow1);
}

TEST(D3D11CompileOptions, PackMatrixFlagShowsInReflection) {
    const std::string source = "float4x4 m; float4 VS(float4 p : POSITION) : SV_Position { return mul(p, m); }";
    ComPtr<ID3DBlob> code;
    ASSERT_EQ(D3DCompile(source.data(), source.size(), "r.hlsl", nullptr, nullptr, "VS", "vs_5_0", D3DCOMPILE_PACK_MATRIX_ROW_MAJOR, 0,
                         code.GetAddressOf(), nullptr),
              S_OK)
        << lastError();
    ComPtr<ID3D11ShaderReflection> r;
    ASSERT_EQ(D3DReflect(code->GetBufferPointer(), code->GetBufferSize(), r.GetAddressOf()), S_OK) << lastError();
    D3D11_SHADER_TYPE_DESC type;
    ASSERT_EQ(r->GetConstantBufferByName("$Globals")->GetVariableByName("m")->GetType()->GetDesc(&type), S_OK);
    EXPECT_EQ(type.Class, D3D_SVC_MATRIX_ROWS);
}

TEST(D3D11CompileOptions, BothPackMatrixFlagsAreInvalid) {
    const std::string source = "float4 VS() : SV_Position { return 0; }";
    ComPtr<ID3DBlob> code, errors;
    EXPECT_EQ(D3DCompile(source.data(), source.size(), "r.hlsl", nullptr, nullptr, "VS", "vs_5_0",
                         D3DCOMPILE_PACK_MATRIX_ROW_MAJOR | D3DCOMPILE_PACK_MATRIX_COLUMN_MAJOR, 0, code.GetAddressOf(), errors.GetAddressOf()),
              E_INVALIDARG);
    EXPECT_FALSE(code);
    EXPECT_NE(lastError().find("Flags1 = 24"), std::string::npos) << lastError();
}

// Headers from memory; records every call.
class MemoryInclude final : public ID3DInclude {
public:
    std::map<std::string, std::string> files;
    struct Call {
        D3D_INCLUDE_TYPE type;
        std::string name;
        std::string parent;  // the file whose data came as pParentData ("" for null)
    };
    std::vector<Call> opens;
    std::multiset<LPCVOID> open;  // opened, not yet closed
    int closes = 0;
    std::vector<std::string> sequence;  // "open NAME" / "close NAME", in call order

    HRESULT Open(D3D_INCLUDE_TYPE type, LPCSTR name, LPCVOID parent, LPCVOID* data, UINT* bytes) override {
        std::string parentName;
        for (const auto& [file, text] : files)
            if (parent == text.data()) parentName = file;
        opens.push_back({type, name, parentName});
        auto it = files.find(name);
        if (it == files.end()) return E_FAIL;
        *data = it->second.data();
        *bytes = UINT(it->second.size());
        open.insert(*data);
        sequence.push_back("open " + std::string(name));
        return S_OK;
    }
    HRESULT Close(LPCVOID data) override {
        ++closes;
        for (const auto& [file, text] : files)
            if (data == text.data()) sequence.push_back("close " + file);
        auto it = open.find(data);
        if (it == open.end()) return E_FAIL;
        open.erase(it);
        return S_OK;
    }
};

TEST(D3D11CompileOptions, IncludeHandlerReadsEveryReachedInclude) {
    MemoryInclude include;
    include.files["outer.hlsli"] = "#include \"inner.hlsli\"\nfloat4 Outer() { return Inner() * 2; }\n";
    include.files["inner.hlsli"] = "float4 Inner() { return float4(1, 2, 3, INNER_W); }\n";
    include.files["system.hlsli"] = "#define INNER_W 4\n";
    const std::string source =
        "#include <system.hlsli>\n#include \"outer.hlsli\"\n#if 0\n#include \"skipped.hlsli\"\n#endif\n"
        "RWBuffer<float4> Out : register(u0);\n[numthreads(1, 1, 1)] void cs() { Out[0] = Outer(); }\n";
    ComPtr<ID3DBlob> code, errors;
    ASSERT_EQ(D3DCompile(source.data(), source.size(), "main.hlsl", nullptr, &include, "cs", "cs_5_0", 0, 0, code.GetAddressOf(),
                         errors.GetAddressOf()),
              S_OK)
        << lastError();
    ASSERT_EQ(include.opens.size(), 3u);
    EXPECT_EQ(include.opens[0].name, "system.hlsli");
    EXPECT_EQ(include.opens[0].type, D3D_INCLUDE_SYSTEM);
    EXPECT_EQ(include.opens[0].parent, "");
    EXPECT_EQ(include.opens[1].name, "outer.hlsli");
    EXPECT_EQ(include.opens[1].type, D3D_INCLUDE_LOCAL);
    EXPECT_EQ(include.opens[2].name, "inner.hlsli");
    EXPECT_EQ(include.opens[2].parent, "outer.hlsli");
    EXPECT_EQ(include.closes, 3);
    EXPECT_TRUE(include.open.empty());
    // D3DCompile closes each file when the preprocessor is done with it: a nested one before its
    // includer, every one before the next #include of an outer file.
    EXPECT_EQ(include.sequence, (std::vector<std::string>{"open system.hlsli", "close system.hlsli", "open outer.hlsli", "open inner.hlsli",
                                                          "close inner.hlsli", "close outer.hlsli"}));

    // The included code is what runs: Outer() = 2 * (1, 2, 3, INNER_W = 4).
    Device d;
    EXPECT_EQ(computedFloat4(d, code.Get(), nullptr), (std::vector<float>{2, 4, 6, 8}));
}

TEST(D3D11CompileOptions, IncludeHandlerFailureNamesTheHeader) {
    MemoryInclude include;
    const std::string source = "#include \"missing.hlsli\"\nfloat4 PS() : SV_Target { return 0; }\n";
    ComPtr<ID3DBlob> code, errors;
    EXPECT_EQ(D3DCompile(source.data(), source.size(), "main.hlsl", nullptr, &include, "PS", "ps_5_0", 0, 0, code.GetAddressOf(),
                         errors.GetAddressOf()),
              E_FAIL);
    EXPECT_FALSE(code);
    ASSERT_TRUE(errors);
    const std::string text(static_cast<const char*>(errors->GetBufferPointer()), errors->GetBufferSize());
    EXPECT_NE(text.find("main.hlsl(1"), std::string::npos) << text;
    EXPECT_NE(text.find("missing.hlsli"), std::string::npos) << text;
    EXPECT_EQ(include.closes, 0);
}

}  // namespace
}  // namespace d3d11test
