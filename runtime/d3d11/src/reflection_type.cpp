// See reflection_type.h.
#include "reflection_type.h"

#include <algorithm>
#include <cstring>

#include "shader_bindings.h"

namespace fxport::d3d11 {

namespace {

using xlate::ParameterClass;

D3D_SHADER_VARIABLE_TYPE typeOf(xlate::ParameterType t) {
    switch (t) {
    case xlate::ParameterType::Bool: return D3D_SVT_BOOL;
    case xlate::ParameterType::Int: return D3D_SVT_INT;
    case xlate::ParameterType::UInt: return D3D_SVT_UINT;
    case xlate::ParameterType::Float: return D3D_SVT_FLOAT;
    default: return D3D_SVT_VOID;
    }
}

D3D_SHADER_VARIABLE_CLASS classOf(const xlate::Parameter& p) {
    switch (p.parameterClass) {
    case ParameterClass::Scalar: return D3D_SVC_SCALAR;
    case ParameterClass::Vector: return D3D_SVC_VECTOR;
    case ParameterClass::Matrix: return p.rowMajor ? D3D_SVC_MATRIX_ROWS : D3D_SVC_MATRIX_COLUMNS;
    case ParameterClass::Object: return D3D_SVC_OBJECT;
    case ParameterClass::Struct: return D3D_SVC_STRUCT;
    }
    return D3D_SVC_SCALAR;
}

// HLSL's spelling of a numeric type: float, float4, float3x4.
std::string typeName(const xlate::Parameter& p) {
    std::string base;
    switch (p.type) {
    case xlate::ParameterType::Bool: base = "bool"; break;
    case xlate::ParameterType::Int: base = "int"; break;
    case xlate::ParameterType::UInt: base = "uint"; break;
    case xlate::ParameterType::Float: base = "float"; break;
    default: return {};
    }
    if (p.parameterClass == ParameterClass::Vector) return base + std::to_string(p.columns);
    if (p.parameterClass == ParameterClass::Matrix) return base + std::to_string(p.rows) + "x" + std::to_string(p.columns);
    return p.parameterClass == ParameterClass::Scalar ? base : std::string();
}

bool startsRegister(const xlate::Parameter& p) {
    return p.elements > 0 || p.parameterClass == ParameterClass::Matrix || p.parameterClass == ParameterClass::Struct;
}

// Each member's offset from the struct's start (D3D's packing: nothing straddles a register;
// arrays, matrices and structs start one); `size` gets the end of the last member.
std::vector<int> memberOffsets(const std::vector<xlate::Parameter>& members, int& size) {
    std::vector<int> offsets;
    int at = 0;
    for (const xlate::Parameter& m : members) {
        const int bytes = d3dPackedSize(m);
        if (startsRegister(m) || (at % 16) + bytes > 16) at = (at + 15) / 16 * 16;
        offsets.push_back(at);
        at += bytes;
    }
    size = at;
    return offsets;
}

}  // namespace

int d3dPackedSize(const xlate::Parameter& p) {
    if (p.parameterClass != ParameterClass::Struct) return packedSize(p);
    int one = 0;
    memberOffsets(p.members, one);
    const int count = std::max(p.elements, 1);
    return (count - 1) * ((one + 15) / 16 * 16) + one;
}

ReflectionType::ReflectionType(const xlate::Parameter& p, int offset) : valid_(true), typeName_(typeName(p)) {
    desc_.Class = classOf(p);
    desc_.Type = typeOf(p.type);
    desc_.Rows = UINT(p.rows);
    desc_.Columns = UINT(p.columns);
    desc_.Elements = UINT(p.elements);
    desc_.Members = UINT(p.members.size());
    desc_.Offset = UINT(offset);
    int size = 0;
    const std::vector<int> offsets = memberOffsets(p.members, size);
    for (std::size_t i = 0; i < p.members.size(); ++i) {
        memberNames_.push_back(p.members[i].name);
        members_.emplace_back(p.members[i], offsets[i]);
    }
}

HRESULT ReflectionType::GetDesc(D3D11_SHADER_TYPE_DESC* p) {
    if (!valid_ || !p) return E_FAIL;
    *p = desc_;
    p->Name = typeName_.c_str();
    return S_OK;
}

ID3D11ShaderReflectionType* ReflectionType::GetMemberTypeByIndex(UINT index) {
    static ReflectionType invalid;
    return index < members_.size() ? &members_[index] : &invalid;
}

ID3D11ShaderReflectionType* ReflectionType::GetMemberTypeByName(LPCSTR name) {
    static ReflectionType invalid;
    for (std::size_t i = 0; name && i < memberNames_.size(); ++i)
        if (memberNames_[i] == name) return &members_[i];
    return &invalid;
}

LPCSTR ReflectionType::GetMemberTypeName(UINT index) { return index < memberNames_.size() ? memberNames_[index].c_str() : nullptr; }

HRESULT ReflectionType::IsEqual(ID3D11ShaderReflectionType* other) {
    auto* o = dynamic_cast<ReflectionType*>(other);
    if (!o || !valid_ || !o->valid_) return S_FALSE;
    const D3D11_SHADER_TYPE_DESC &a = desc_, &b = o->desc_;
    if (a.Class != b.Class || a.Type != b.Type || a.Rows != b.Rows || a.Columns != b.Columns || a.Elements != b.Elements ||
        a.Members != b.Members || typeName_ != o->typeName_ || memberNames_ != o->memberNames_)
        return S_FALSE;
    for (std::size_t i = 0; i < members_.size(); ++i)
        if (members_[i].IsEqual(&o->members_[i]) != S_OK || members_[i].desc_.Offset != o->members_[i].desc_.Offset) return S_FALSE;
    return S_OK;
}

}  // namespace fxport::d3d11
