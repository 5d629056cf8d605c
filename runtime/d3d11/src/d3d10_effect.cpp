// The D3D10 effects framework (fxport/d3d10/d3dx10effect.h) over the D3DX11 one: the effect is
// compiled from its file (D3DCompileFromFile, so a failure leaves the compiler's messages in
// ppErrors) and made by D3DX11CreateEffectFromMemory; techniques and passes wrap D3DX11's, a pass's
// Apply(0) applying the D3DX11 pass on the device's immediate context. Variables are D3DX11's.
#include <atomic>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "d3d11_impl.h"
#include "fxport/d3d10.h"

namespace fxport::d3d10 {

namespace {

class Pass10 final : public ID3D10EffectPass {
public:
    Pass10(ID3DX11EffectPass* pass, ID3D11DeviceContext* context) : pass_(pass), context_(context) {}
    BOOL IsValid() override { return pass_->IsValid(); }
    HRESULT GetDesc(D3D10_PASS_DESC* pDesc) override { return pass_->GetDesc(pDesc); }
    HRESULT Apply(UINT Flags) override { return pass_->Apply(Flags, context_); }

private:
    ID3DX11EffectPass* pass_;
    ID3D11DeviceContext* context_;
};

class Technique10 final : public ID3D10EffectTechnique {
public:
    Technique10(ID3DX11EffectTechnique* technique, ID3D11DeviceContext* context) : technique_(technique), context_(context) {}
    BOOL IsValid() override { return technique_->IsValid(); }
    HRESULT GetDesc(D3D10_TECHNIQUE_DESC* pDesc) override { return technique_->GetDesc(pDesc); }
    ID3D10EffectPass* GetPassByIndex(UINT Index) override { return wrap(technique_->GetPassByIndex(Index)); }
    ID3D10EffectPass* GetPassByName(LPCSTR Name) override { return wrap(technique_->GetPassByName(Name)); }

private:
    // One wrapper per D3DX11 pass (they live as long as the effect, as D3DX11's do).
    ID3D10EffectPass* wrap(ID3DX11EffectPass* pass) {
        std::unique_ptr<Pass10>& p = passes_[pass];
        if (!p) p = std::make_unique<Pass10>(pass, context_);
        return p.get();
    }
    ID3DX11EffectTechnique* technique_;
    ID3D11DeviceContext* context_;
    std::map<ID3DX11EffectPass*, std::unique_ptr<Pass10>> passes_;
};

class Effect10 final : public ID3D10Effect {
public:
    Effect10(ComPtr<ID3DX11Effect> effect, ComPtr<ID3D10Device> device) : effect_(std::move(effect)), device_(std::move(device)) {}
    ULONG AddRef() override { return ++references_; }
    ULONG Release() override {
        const ULONG left = --references_;
        if (left == 0) delete this;
        return left;
    }
    BOOL IsValid() override { return effect_->IsValid(); }
    HRESULT GetDesc(D3D10_EFFECT_DESC* pDesc) override { return effect_->GetDesc(pDesc); }
    ID3D10EffectTechnique* GetTechniqueByIndex(UINT Index) override { return wrap(effect_->GetTechniqueByIndex(Index)); }
    ID3D10EffectTechnique* GetTechniqueByName(LPCSTR Name) override { return wrap(effect_->GetTechniqueByName(Name)); }
    ID3D10EffectVariable* GetVariableByName(LPCSTR Name) override { return effect_->GetVariableByName(Name); }
    ID3D10EffectVariable* GetVariableBySemantic(LPCSTR Semantic) override { return effect_->GetVariableBySemantic(Semantic); }
    ID3DX11Effect* GetD3DX11Effect() override { return effect_.Get(); }

private:
    ID3D10EffectTechnique* wrap(ID3DX11EffectTechnique* technique) {
        std::unique_ptr<Technique10>& t = techniques_[technique];
        if (!t) t = std::make_unique<Technique10>(technique, device_->GetD3D11Context());
        return t.get();
    }
    ComPtr<ID3DX11Effect> effect_;
    ComPtr<ID3D10Device> device_;
    std::map<ID3DX11EffectTechnique*, std::unique_ptr<Technique10>> techniques_;
    std::atomic<ULONG> references_{1};
};

template <class Path>
HRESULT createEffect(const char* call, Path fileName, const D3D10_SHADER_MACRO* defines, ID3D10Include* include, LPCSTR profile, UINT hlslFlags,
                     ID3D10Device* device, ID3D10EffectPool* pool, void* pump, ID3D10Effect** ppEffect, ID3D10Blob** ppErrors) {
    const std::string at = std::string(call) + ": ";
    if (!fileName) return d3d11::fail(E_INVALIDARG, at + "pFileName is null");
    if (!device) return d3d11::fail(E_INVALIDARG, at + "pDevice is null");
    if (pool) return d3d11::fail(E_NOTIMPL, at + "effect pools (pEffectPool) are not supported; pass NULL");
    if (pump) return d3d11::fail(E_NOTIMPL, at + "pPump (asynchronous loading) is not supported; pass NULL");
    if (!profile || std::string(profile).rfind("fx_", 0) != 0)
        return d3d11::fail(E_INVALIDARG, at + "pProfile = " + std::string(profile ? profile : "(null)") + " (an effect profile: fx_4_0, fx_4_1, fx_5_0)");
    ComPtr<ID3DBlob> code;
    HRESULT hr = D3DCompileFromFile(fileName, defines, include, nullptr, profile, hlslFlags, 0, code.GetAddressOf(), ppErrors);
    if (FAILED(hr)) return hr;
    ComPtr<ID3DX11Effect> effect;
    hr = D3DX11CreateEffectFromMemory(code->GetBufferPointer(), code->GetBufferSize(), 0, device->GetD3D11Device(), effect.GetAddressOf());
    if (FAILED(hr)) return hr;
    if (ppEffect) *ppEffect = new Effect10(effect, ComPtr<ID3D10Device>(device));
    return d3d11::succeed();
}

}  // namespace

HRESULT D3DX10CreateEffectFromFile(const wchar_t* pFileName, const D3D10_SHADER_MACRO* pDefines, ID3D10Include* pInclude, LPCSTR pProfile,
                                   UINT HLSLFlags, UINT, ID3D10Device* pDevice, ID3D10EffectPool* pEffectPool, void* pPump,
                                   ID3D10Effect** ppEffect, ID3D10Blob** ppErrors, HRESULT* pHResult) {
    const HRESULT hr = createEffect("D3DX10CreateEffectFromFile", pFileName, pDefines, pInclude, pProfile, HLSLFlags, pDevice, pEffectPool, pPump,
                                    ppEffect, ppErrors);
    if (pHResult) *pHResult = hr;
    return hr;
}

HRESULT D3DX10CreateEffectFromFile(LPCSTR pFileName, const D3D10_SHADER_MACRO* pDefines, ID3D10Include* pInclude, LPCSTR pProfile,
                                   UINT HLSLFlags, UINT, ID3D10Device* pDevice, ID3D10EffectPool* pEffectPool, void* pPump,
                                   ID3D10Effect** ppEffect, ID3D10Blob** ppErrors, HRESULT* pHResult) {
    const HRESULT hr = createEffect("D3DX10CreateEffectFromFile", pFileName, pDefines, pInclude, pProfile, HLSLFlags, pDevice, pEffectPool, pPump,
                                    ppEffect, ppErrors);
    if (pHResult) *pHResult = hr;
    return hr;
}

}  // namespace fxport::d3d10
