// The D3D10 effects framework with D3D10's names (ID3D10Effect, D3DX10CreateEffectFromFile) as
// the Rastertek DX10 tutorials use it, over fxport's D3DX11 effects (d3dx11effect.h): one
// implementation underneath. Variables are D3DX11's (ID3D10EffectMatrixVariable is
// ID3DX11EffectMatrixVariable: SetMatrix, AsShaderResource()->SetResource ...); techniques and
// passes are thin adapters, since D3D10's pass Apply(0) takes no context (the device is one).
//
//   ID3D10Effect* effect;  ID3D10Blob* errors;
//   D3DX10CreateEffectFromFile(L"deferred.fx", NULL, NULL, "fx_4_0", D3D10_SHADER_ENABLE_STRICTNESS, 0,
//                              device, NULL, NULL, &effect, &errors, NULL);
//   effect->GetVariableByName("worldMatrix")->AsMatrix()->SetMatrix((float*)&world);
//   effect->GetTechniqueByName("DeferredTechnique")->GetPassByIndex(0)->Apply(0);
#pragma once

#include "fxport/d3d10/d3d10_interfaces.h"
#include "fxport/d3d11/d3dcompiler.h"
#include "fxport/d3d11/d3dx11effect.h"

namespace fxport::d3d10 {

using D3D10_TECHNIQUE_DESC = D3DX11_TECHNIQUE_DESC;
using D3D10_PASS_DESC = D3DX11_PASS_DESC;
using D3D10_EFFECT_DESC = D3DX11_EFFECT_DESC;
using D3D10_EFFECT_VARIABLE_DESC = D3DX11_EFFECT_VARIABLE_DESC;
using D3D10_SHADER_MACRO = D3D_SHADER_MACRO;
using ID3D10Include = ID3DInclude;
using ID3D10EffectVariable = ID3DX11EffectVariable;
using ID3D10EffectScalarVariable = ID3DX11EffectScalarVariable;
using ID3D10EffectVectorVariable = ID3DX11EffectVectorVariable;
using ID3D10EffectMatrixVariable = ID3DX11EffectMatrixVariable;
using ID3D10EffectShaderResourceVariable = ID3DX11EffectShaderResourceVariable;
class ID3D10EffectPool;  // effect pools are not supported (pEffectPool must be null)

// Passes and techniques live as long as their effect; a name or index that does not exist gives
// an object whose IsValid() is FALSE and whose calls fail with E_FAIL.
class ID3D10EffectPass {
public:
    virtual BOOL IsValid() = 0;
    virtual HRESULT GetDesc(D3D10_PASS_DESC* pDesc) = 0;
    // Makes the device's next draws run the pass (its shaders, the effect's constants and
    // textures, the states it sets); Flags must be 0.
    virtual HRESULT Apply(UINT Flags) = 0;

protected:
    ~ID3D10EffectPass() = default;
};
class ID3D10EffectTechnique {
public:
    virtual BOOL IsValid() = 0;
    virtual HRESULT GetDesc(D3D10_TECHNIQUE_DESC* pDesc) = 0;
    virtual ID3D10EffectPass* GetPassByIndex(UINT Index) = 0;
    virtual ID3D10EffectPass* GetPassByName(LPCSTR Name) = 0;

protected:
    ~ID3D10EffectTechnique() = default;
};
class ID3D10Effect : public IUnknown {
public:
    virtual BOOL IsValid() = 0;
    virtual HRESULT GetDesc(D3D10_EFFECT_DESC* pDesc) = 0;
    virtual ID3D10EffectTechnique* GetTechniqueByIndex(UINT Index) = 0;
    virtual ID3D10EffectTechnique* GetTechniqueByName(LPCSTR Name) = 0;
    virtual ID3D10EffectVariable* GetVariableByName(LPCSTR Name) = 0;
    virtual ID3D10EffectVariable* GetVariableBySemantic(LPCSTR Semantic) = 0;
    // fxport: the D3DX11 effect underneath (no reference added).
    virtual ID3DX11Effect* GetD3DX11Effect() = 0;
};

// Compiles the .fx file for pProfile (fx_4_0 / fx_4_1 / fx_5_0) and makes the effect on pDevice.
// On a compile failure *ppErrors (when given) holds the compiler's messages, as D3DX10's does.
// pEffectPool and pPump must be null; pHResult, when given, receives the result too.
HRESULT D3DX10CreateEffectFromFile(const wchar_t* pFileName, const D3D10_SHADER_MACRO* pDefines, ID3D10Include* pInclude, LPCSTR pProfile,
                                   UINT HLSLFlags, UINT FXFlags, ID3D10Device* pDevice, ID3D10EffectPool* pEffectPool, void* pPump,
                                   ID3D10Effect** ppEffect, ID3D10Blob** ppErrors, HRESULT* pHResult);
HRESULT D3DX10CreateEffectFromFile(LPCSTR pFileName, const D3D10_SHADER_MACRO* pDefines, ID3D10Include* pInclude, LPCSTR pProfile,
                                   UINT HLSLFlags, UINT FXFlags, ID3D10Device* pDevice, ID3D10EffectPool* pEffectPool, void* pPump,
                                   ID3D10Effect** ppEffect, ID3D10Blob** ppErrors, HRESULT* pHResult);

}  // namespace fxport::d3d10
