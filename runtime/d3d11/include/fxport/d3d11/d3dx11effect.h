// The D3DX11 effects framework (Effects11's d3dx11effect.h) with its names: ID3DX11Effect, its
// techniques, passes and typed variables, over the same compiled effects the XNA Effect uses (one
// fxport::Effect underneath). A pass's Apply(0, context) makes the next draws of that context run
// the pass's shaders with the effect's constants, textures and the states the pass sets; a later
// VSSetShader/PSSetShader ends it, as it replaces the pass's shaders in D3D.
//
//   ComPtr<ID3DBlob> fx;  D3DX11CompileFromFile("light.fx", nullptr, nullptr, nullptr, "fx_5_0", 0, 0,
//                                               nullptr, fx.GetAddressOf(), nullptr, nullptr);
//   D3DX11CreateEffectFromMemory(fx->GetBufferPointer(), fx->GetBufferSize(), 0, device, effect.GetAddressOf());
//   effect->GetVariableByName("World")->AsMatrix()->SetMatrix(&world._11);
//   effect->GetTechniqueByName("Light")->GetPassByIndex(0)->Apply(0, context);
#pragma once

#include "fxport/d3d11/d3d11_interfaces.h"

namespace fxport::d3d11 {

struct D3DX11_EFFECT_DESC {
    UINT ConstantBuffers = 0;
    UINT GlobalVariables = 0;
    UINT InterfaceVariables = 0;
    UINT Techniques = 0;
    UINT Groups = 0;
};
struct D3DX11_TECHNIQUE_DESC {
    LPCSTR Name = nullptr;
    UINT Passes = 0;
    UINT Annotations = 0;
};
struct D3DX11_PASS_DESC {
    LPCSTR Name = nullptr;
    UINT Annotations = 0;
    UINT8* pIAInputSignature = nullptr;  // the pass's vertex shader: what CreateInputLayout takes
    SIZE_T IAInputSignatureSize = 0;
    UINT StencilRef = 0;
    UINT SampleMask = 0xffffffffu;
    FLOAT BlendFactor[4] = {0, 0, 0, 0};
};
struct D3DX11_EFFECT_VARIABLE_DESC {
    LPCSTR Name = nullptr;
    LPCSTR Semantic = nullptr;
    UINT Flags = 0;
    UINT Annotations = 0;
    UINT BufferOffset = 0;
    UINT ExplicitBindPoint = 0;
};

class ID3DX11EffectScalarVariable;
class ID3DX11EffectVectorVariable;
class ID3DX11EffectMatrixVariable;
class ID3DX11EffectShaderResourceVariable;

// Variables, techniques and passes live as long as their effect (no reference counts, as in
// Effects11). A name or index that does not exist gives an object whose IsValid() is FALSE and
// whose calls fail with E_FAIL (Effects11's "invalid" objects); As*() of the wrong kind too.
class ID3DX11EffectVariable {
public:
    virtual BOOL IsValid() = 0;
    virtual HRESULT GetDesc(D3DX11_EFFECT_VARIABLE_DESC* pDesc) = 0;
    virtual ID3DX11EffectScalarVariable* AsScalar() = 0;
    virtual ID3DX11EffectVectorVariable* AsVector() = 0;
    virtual ID3DX11EffectMatrixVariable* AsMatrix() = 0;
    virtual ID3DX11EffectShaderResourceVariable* AsShaderResource() = 0;

protected:
    ~ID3DX11EffectVariable() = default;
};
class ID3DX11EffectScalarVariable : public ID3DX11EffectVariable {
public:
    virtual HRESULT SetFloat(float Value) = 0;
    virtual HRESULT SetInt(int Value) = 0;
    virtual HRESULT SetBool(BOOL Value) = 0;
    virtual HRESULT SetFloatArray(const float* pData, UINT Offset, UINT Count) = 0;
    virtual HRESULT GetFloat(float* pValue) = 0;

protected:
    ~ID3DX11EffectScalarVariable() = default;
};
class ID3DX11EffectVectorVariable : public ID3DX11EffectVariable {
public:
    // As many floats as the variable has components (float3: 3).
    virtual HRESULT SetFloatVector(const float* pData) = 0;
    virtual HRESULT SetFloatVectorArray(const float* pData, UINT Offset, UINT Count) = 0;  // 4 floats per element
    virtual HRESULT GetFloatVector(float* pData) = 0;

protected:
    ~ID3DX11EffectVectorVariable() = default;
};
class ID3DX11EffectMatrixVariable : public ID3DX11EffectVariable {
public:
    // 16 floats, row by row (XMFLOAT4X4's order): HLSL sees M[r][c] = pData[r * 4 + c], whatever
    // the variable's packing.
    virtual HRESULT SetMatrix(const float* pData) = 0;
    virtual HRESULT SetMatrixTranspose(const float* pData) = 0;
    virtual HRESULT SetMatrixArray(const float* pData, UINT Offset, UINT Count) = 0;
    virtual HRESULT GetMatrix(float* pData) = 0;

protected:
    ~ID3DX11EffectMatrixVariable() = default;
};
class ID3DX11EffectShaderResourceVariable : public ID3DX11EffectVariable {
public:
    virtual HRESULT SetResource(ID3D11ShaderResourceView* pResource) = 0;

protected:
    ~ID3DX11EffectShaderResourceVariable() = default;
};

class ID3DX11EffectPass {
public:
    virtual BOOL IsValid() = 0;
    virtual HRESULT GetDesc(D3DX11_PASS_DESC* pDesc) = 0;
    virtual HRESULT Apply(UINT Flags, ID3D11DeviceContext* pContext) = 0;

protected:
    ~ID3DX11EffectPass() = default;
};
class ID3DX11EffectTechnique {
public:
    virtual BOOL IsValid() = 0;
    virtual HRESULT GetDesc(D3DX11_TECHNIQUE_DESC* pDesc) = 0;
    virtual ID3DX11EffectPass* GetPassByIndex(UINT Index) = 0;
    virtual ID3DX11EffectPass* GetPassByName(LPCSTR Name) = 0;

protected:
    ~ID3DX11EffectTechnique() = default;
};
class ID3DX11Effect : public IUnknown {
public:
    virtual BOOL IsValid() = 0;
    virtual HRESULT GetDesc(D3DX11_EFFECT_DESC* pDesc) = 0;
    virtual ID3DX11EffectTechnique* GetTechniqueByIndex(UINT Index) = 0;
    virtual ID3DX11EffectTechnique* GetTechniqueByName(LPCSTR Name) = 0;
    virtual ID3DX11EffectVariable* GetVariableByName(LPCSTR Name) = 0;
    virtual ID3DX11EffectVariable* GetVariableBySemantic(LPCSTR Semantic) = 0;
};

// From an effect compiled by D3DCompile / D3DX11CompileFromFile with an fx_4_0 / fx_5_0 target.
HRESULT D3DX11CreateEffectFromMemory(const void* pData, SIZE_T DataLength, UINT FXFlags, ID3D11Device* pDevice,
                                     ID3DX11Effect** ppEffect, LPCSTR srcName = nullptr);
// fxport: from the .fx source itself (compiled through fxport's cache; Effects11 reads a compiled
// .fxo here). Techniques compile at their first Apply, as the XNA Effect's do.
HRESULT D3DX11CreateEffectFromFile(LPCSTR pFileName, UINT FXFlags, ID3D11Device* pDevice, ID3DX11Effect** ppEffect);
HRESULT D3DX11CreateEffectFromFile(const wchar_t* pFileName, UINT FXFlags, ID3D11Device* pDevice, ID3DX11Effect** ppEffect);

}  // namespace fxport::d3d11
