// ID3D11ShaderReflectionType beyond GetDesc: a struct variable's members by index and name, their
// names, types and offsets (from the struct's start, worked out here by hand from D3D's packing
// rules: nothing straddles a 16-byte register; arrays, matrices and structs start one), IsEqual,
// and the stand-in object D3D returns for an index or name that does not exist.
#include "d3d11_test_support.h"

namespace d3d11test {
namespace {

const char* kStruct = R"(
struct Light {
    float3 dir;        // 0, 12 bytes
    float intensity;   // 12
    float2 uv;         // 16
    float4x4 m;        // a matrix starts a register: 32, 64 bytes
    float arr[2];      // an array starts a register: 96, 16 + 4 = 20 bytes
    float tail;        // 116: fits the array's last register
    float3 last;       // 120 + 12 would straddle: 128
};
cbuffer C { Light light; float3 other; };
float4 VS(float4 p : POSITION) : SV_Position {
    return p * (light.dir.x + light.intensity + light.uv.y + light.m[1][2] + light.arr[1] + light.tail + light.last.z + other.z);
}
)";

struct Member {
    const char* name;
    D3D_SHADER_VARIABLE_CLASS cls;
    const char* typeName;
    UINT rows, columns, elements, offset;
};

TEST(D3D11ReflectionType, StructMembersHaveD3DOffsetsNamesAndTypes) {
    ComPtr<ID3DBlob> vs = compile(kStruct, "VS", "vs_5_0", "struct.hlsl");
    ASSERT_TRUE(vs);
    ComPtr<ID3D11ShaderReflection> r;
    ASSERT_EQ(D3DReflect(vs->GetBufferPointer(), vs->GetBufferSize(), r.GetAddressOf()), S_OK) << lastError();
    ID3D11ShaderReflectionType* light = r->GetConstantBufferByName("C")->GetVariableByName("light")->GetType();
    D3D11_SHADER_TYPE_DESC desc;
    ASSERT_EQ(light->GetDesc(&desc), S_OK);
    EXPECT_EQ(desc.Class, D3D_SVC_STRUCT);
    ASSERT_EQ(desc.Members, 7u);
    EXPECT_STREQ(desc.Name, "");  // fxport does not record a struct's type name
    const Member expected[] = {
        {"dir", D3D_SVC_VECTOR, "float3", 1, 3, 0, 0},         {"intensity", D3D_SVC_SCALAR, "float", 1, 1, 0, 12},
        {"uv", D3D_SVC_VECTOR, "float2", 1, 2, 0, 16},         {"m", D3D_SVC_MATRIX_COLUMNS, "float4x4", 4, 4, 0, 32},
        {"arr", D3D_SVC_SCALAR, "float", 1, 1, 2, 96},         {"tail", D3D_SVC_SCALAR, "float", 1, 1, 0, 116},
        {"last", D3D_SVC_VECTOR, "float3", 1, 3, 0, 128},
    };
    for (UINT i = 0; i < 7; ++i) {
        const Member& e = expected[i];
        EXPECT_STREQ(light->GetMemberTypeName(i), e.name);
        ID3D11ShaderReflectionType* byIndex = light->GetMemberTypeByIndex(i);
        EXPECT_EQ(byIndex, light->GetMemberTypeByName(e.name)) << e.name;
        D3D11_SHADER_TYPE_DESC m;
        ASSERT_EQ(byIndex->GetDesc(&m), S_OK) << e.name;
        EXPECT_EQ(m.Class, e.cls) << e.name;
        EXPECT_EQ(m.Type, e.cls == D3D_SVC_STRUCT ? D3D_SVT_VOID : D3D_SVT_FLOAT) << e.name;
        EXPECT_STREQ(m.Name, e.typeName) << e.name;
        if (e.cls != D3D_SVC_STRUCT) {
            EXPECT_EQ(m.Rows, e.rows) << e.name;
            EXPECT_EQ(m.Columns, e.columns) << e.name;
        }
        EXPECT_EQ(m.Elements, e.elements) << e.name;
        EXPECT_EQ(m.Offset, e.offset) << e.name;
    }
    D3D11_SHADER_TYPE_DESC m;
    // IsEqual: the same type is equal wherever it is; another is not.
    ID3D11ShaderReflectionType* other = r->GetConstantBufferByName("C")->GetVariableByName("other")->GetType();
    EXPECT_EQ(light->GetMemberTypeByName("dir")->IsEqual(light->GetMemberTypeByName("dir")), S_OK);
    EXPECT_EQ(light->GetMemberTypeByName("intensity")->IsEqual(light->GetMemberTypeByName("tail")), S_OK);
    EXPECT_EQ(light->GetMemberTypeByName("dir")->IsEqual(light->GetMemberTypeByName("uv")), S_FALSE);
    EXPECT_EQ(other->IsEqual(light), S_FALSE);

    // What does not exist: D3D's stand-in, whose GetDesc fails; no name.
    EXPECT_EQ(light->GetMemberTypeByIndex(7)->GetDesc(&m), E_FAIL);
    EXPECT_EQ(light->GetMemberTypeByName("nope")->GetDesc(&m), E_FAIL);
    EXPECT_EQ(light->GetMemberTypeName(7), nullptr);
    EXPECT_EQ(other->GetMemberTypeByIndex(0)->GetDesc(&m), E_FAIL);
}

}  // namespace
}  // namespace d3d11test
