// INTERNAL: ID3D11ShaderReflectionType over a compiled parameter: its D3D description and, for a
// struct, its members at D3D's packed offsets (from the struct's start), recursively.
#pragma once

#include <deque>
#include <string>

#include "fxport/d3d11/d3dcompiler.h"
#include "fxport/xlate/compiled_effect.h"

namespace fxport::d3d11 {

class ReflectionType final : public ID3D11ShaderReflectionType {
public:
    ReflectionType() = default;  // invalid: GetDesc fails, as D3D's stand-in objects do
    // `offset`: the member's offset in its struct (0 for a variable).
    ReflectionType(const xlate::Parameter& p, int offset);

    HRESULT GetDesc(D3D11_SHADER_TYPE_DESC* pDesc) override;
    ID3D11ShaderReflectionType* GetMemberTypeByIndex(UINT index) override;
    ID3D11ShaderReflectionType* GetMemberTypeByName(LPCSTR name) override;
    LPCSTR GetMemberTypeName(UINT index) override;
    HRESULT IsEqual(ID3D11ShaderReflectionType* other) override;

private:
    bool valid_ = false;
    D3D11_SHADER_TYPE_DESC desc_;
    std::string typeName_;
    std::deque<std::string> memberNames_;
    std::deque<ReflectionType> members_;  // deque: the addresses handed out stay put
};

// D3D's size in bytes of `p` in a constant buffer (structs packed member by member; arrays'
// elements start registers; no padding after the last component).
int d3dPackedSize(const xlate::Parameter& p);

}  // namespace fxport::d3d11
