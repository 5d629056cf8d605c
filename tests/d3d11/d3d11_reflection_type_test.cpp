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

// Structs three levels deep, and an array of structs inside a struct: every level's members at
// D3D's offsets from their own struct's start (worked out by hand below), recursively through
// GetMemberTypeByIndex / ByName, and the cbuffer variables after them packed into their trailing space.
const char* kNested = R"(
struct Inner { float a; float2 b; };                 // a 0, b 4: 12 bytes
struct Middle { float3 c; Inner inner; float d; };   // c 0; inner starts a register: 16 (12 bytes); d 28: 32 bytes
struct Outer { float e; Middle m; Inner arr[2]; };   // e 0; m 16; arr 48, elements 16 apart: 48 + 16 + 12 = 76 bytes
cbuffer N { float head; Outer o; float tail; };      // head 0; o 16 (76 bytes, to 92); tail 92
float4 VS(float4 p : POSITION) : SV_Position {
    return p * (head + o.e + o.m.c.y + o.m.inner.a + o.m.inner.b.y + o.m.d + o.arr[1].a + o.arr[0].b.x + tail);
}
)";

UINT offsetOf(ID3D11ShaderReflectionType* t) {
    D3D11_SHADER_TYPE_DESC d;
    return t->GetDesc(&d) == S_OK ? d.Offset : 0xffffffffu;
}
UINT membersOf(ID3D11ShaderReflectionType* t) {
    D3D11_SHADER_TYPE_DESC d;
    return t->GetDesc(&d) == S_OK ? d.Members : 0xffffffffu;
}

TEST(D3D11ReflectionType, NestedStructsHaveD3DOffsetsAtEveryLevel) {
    ComPtr<ID3DBlob> vs = compile(kNested, "VS", "vs_5_0", "nested.hlsl");
    ASSERT_TRUE(vs);
    ComPtr<ID3D11ShaderReflection> r;
    ASSERT_EQ(D3DReflect(vs->GetBufferPointer(), vs->GetBufferSize(), r.GetAddressOf()), S_OK) << lastError();
    ID3D11ShaderReflectionConstantBuffer* cb = r->GetConstantBufferByName("N");
    D3D11_SHADER_VARIABLE_DESC v;
    ASSERT_EQ(cb->GetVariableByName("o")->GetDesc(&v), S_OK);
    EXPECT_EQ(v.StartOffset, 16u);
    EXPECT_EQ(v.Size, 76u);
    ASSERT_EQ(cb->GetVariableByName("tail")->GetDesc(&v), S_OK);
    EXPECT_EQ(v.StartOffset, 92u);

    ID3D11ShaderReflectionType* outer = cb->GetVariableByName("o")->GetType();
    ASSERT_EQ(membersOf(outer), 3u);
    EXPECT_EQ(offsetOf(outer->GetMemberTypeByName("e")), 0u);
    ID3D11ShaderReflectionType* middle = outer->GetMemberTypeByName("m");
    EXPECT_EQ(offsetOf(middle), 16u);
    ASSERT_EQ(membersOf(middle), 3u);
    EXPECT_EQ(offsetOf(middle->GetMemberTypeByIndex(0)), 0u);   // c
    ID3D11ShaderReflectionType* inner = middle->GetMemberTypeByIndex(1);
    EXPECT_STREQ(middle->GetMemberTypeName(1), "inner");
    EXPECT_EQ(offsetOf(inner), 16u);
    EXPECT_EQ(offsetOf(middle->GetMemberTypeByName("d")), 28u);
    ASSERT_EQ(membersOf(inner), 2u);  // the third level
    EXPECT_EQ(offsetOf(inner->GetMemberTypeByName("a")), 0u);
    EXPECT_EQ(offsetOf(inner->GetMemberTypeByName("b")), 4u);
    D3D11_SHADER_TYPE_DESC b;
    ASSERT_EQ(inner->GetMemberTypeByName("b")->GetDesc(&b), S_OK);
    EXPECT_EQ(b.Class, D3D_SVC_VECTOR);
    EXPECT_EQ(b.Columns, 2u);

    ID3D11ShaderReflectionType* arr = outer->GetMemberTypeByName("arr");
    D3D11_SHADER_TYPE_DESC a;
    ASSERT_EQ(arr->GetDesc(&a), S_OK);
    EXPECT_EQ(a.Class, D3D_SVC_STRUCT);
    EXPECT_EQ(a.Elements, 2u);
    EXPECT_EQ(a.Offset, 48u);
    ASSERT_EQ(a.Members, 2u);
    EXPECT_EQ(offsetOf(arr->GetMemberTypeByName("b")), 4u);  // within one element
    EXPECT_EQ(arr->GetMemberTypeByName("a")->IsEqual(inner->GetMemberTypeByName("a")), S_OK);
}

}  // namespace
}  // namespace d3d11test
