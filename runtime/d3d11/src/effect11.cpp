// The D3DX11 effects framework over fxport::Effect (d3dx11effect.h): variables set the effect's
// parameters (one constant store, the XNA Effect's), a pass's Apply hands the fxport EffectPass to
// the context, which applies it at each draw in place of its own VS/PS bindings.
#include <deque>
#include <map>

#include "context.h"
#include "fxport/d3d11/core_access.h"
#include "fxport/xlate/diagnostics.h"
#include "fxport/xlate/effect_file.h"
#include "guarded.h"

namespace fxport::d3d11 {

namespace {

class Effect11;

// One effect variable; the typed views below answer As*() and forward the common calls here.
class Variable final : public ID3DX11EffectVariable {
public:
    Variable(Effect11* owner, EffectParameter* parameter) : owner_(owner), parameter_(parameter), scalar_(*this), vector_(*this), matrix_(*this), resource_(*this) {}
    BOOL IsValid() override { return parameter_ != nullptr; }
    HRESULT GetDesc(D3DX11_EFFECT_VARIABLE_DESC* pDesc) override {
        if (!parameter_ || !pDesc) return fail(E_FAIL, "ID3DX11EffectVariable::GetDesc: an invalid variable");
        *pDesc = D3DX11_EFFECT_VARIABLE_DESC{};
        pDesc->Name = parameter_->Name().c_str();
        pDesc->Semantic = parameter_->Semantic().empty() ? nullptr : parameter_->Semantic().c_str();
        pDesc->Annotations = UINT(parameter_->Annotations().size());
        return S_OK;
    }
    ID3DX11EffectScalarVariable* AsScalar() override { return &scalar_; }
    ID3DX11EffectVectorVariable* AsVector() override { return &vector_; }
    ID3DX11EffectMatrixVariable* AsMatrix() override { return &matrix_; }
    ID3DX11EffectShaderResourceVariable* AsShaderResource() override { return &resource_; }

    EffectParameter* parameter() const { return parameter_; }
    Effect11* owner() const { return owner_; }
    // Runs `set` on the parameter if it is of `kind`; E_FAIL naming the variable otherwise.
    template <class F>
    HRESULT set(const char* call, bool kindMatches, F&& f) {
        if (!parameter_) return fail(E_FAIL, std::string(call) + ": an invalid variable (no such name in the effect)");
        if (!kindMatches)
            return fail(E_FAIL, std::string(call) + ": variable '" + parameter_->Name() + "' is not of this kind (As*() of the wrong type)");
        return guarded(call, [&] {
            f(*parameter_);
            return succeed();
        });
    }
    bool is(EffectParameterClass c) const { return parameter_ && parameter_->ParameterClass() == c; }

private:
    // A typed view: the common calls go to the variable.
    template <class Interface>
    class View : public Interface {
    public:
        explicit View(Variable& v) : v_(v) {}
        BOOL IsValid() override { return v_.IsValid(); }
        HRESULT GetDesc(D3DX11_EFFECT_VARIABLE_DESC* pDesc) override { return v_.GetDesc(pDesc); }
        ID3DX11EffectScalarVariable* AsScalar() override { return v_.AsScalar(); }
        ID3DX11EffectVectorVariable* AsVector() override { return v_.AsVector(); }
        ID3DX11EffectMatrixVariable* AsMatrix() override { return v_.AsMatrix(); }
        ID3DX11EffectShaderResourceVariable* AsShaderResource() override { return v_.AsShaderResource(); }

    protected:
        ~View() = default;
        Variable& v_;
    };

    class Scalar final : public View<ID3DX11EffectScalarVariable> {
    public:
        using View::View;
        HRESULT SetFloat(float value) override { return setNumber("SetFloat", value); }
        HRESULT SetInt(int value) override { return setNumber("SetInt", double(value)); }
        HRESULT SetBool(BOOL value) override { return setNumber("SetBool", value ? 1.0 : 0.0); }
        HRESULT SetFloatArray(const float* data, UINT offset, UINT count) override {
            return v_.set("SetFloatArray", v_.is(EffectParameterClass::Scalar) && data, [&](EffectParameter& p) {
                std::vector<float> all = p.GetValueSingleArray();
                if (std::size_t(offset) + count > all.size()) throw ArgumentError("elements [" + std::to_string(offset) + ", " +
                                                                                  std::to_string(offset + count) + ") of " + std::to_string(all.size()));
                std::copy(data, data + count, all.begin() + offset);
                p.SetValue(std::span<const float>(all));
            });
        }
        HRESULT GetFloat(float* value) override {
            return v_.set("GetFloat", v_.is(EffectParameterClass::Scalar) && value, [&](EffectParameter& p) { *value = p.GetValueSingleArray().at(0); });
        }

    private:
        // D3DX converts between the scalar types; so does this.
        HRESULT setNumber(const char* call, double value) {
            return v_.set(call, v_.is(EffectParameterClass::Scalar), [&](EffectParameter& p) {
                switch (p.ParameterType()) {
                case EffectParameterType::Bool: p.SetValue(value != 0); break;
                case EffectParameterType::Int32: p.SetValue(int(value)); break;
                default: p.SetValue(float(value)); break;
                }
            });
        }
    };

    class Vector final : public View<ID3DX11EffectVectorVariable> {
    public:
        using View::View;
        HRESULT SetFloatVector(const float* data) override {
            return v_.set("SetFloatVector", v_.is(EffectParameterClass::Vector) && data, [&](EffectParameter& p) {
                std::vector<float> all = p.GetValueSingleArray();
                std::copy(data, data + p.ColumnCount(), all.begin());
                p.SetValue(std::span<const float>(all));
            });
        }
        HRESULT SetFloatVectorArray(const float* data, UINT offset, UINT count) override {
            return v_.set("SetFloatVectorArray", v_.is(EffectParameterClass::Vector) && data, [&](EffectParameter& p) {
                std::vector<float> all = p.GetValueSingleArray();
                const std::size_t n = std::size_t(p.ColumnCount());
                if ((std::size_t(offset) + count) * n > all.size())
                    throw ArgumentError("elements [" + std::to_string(offset) + ", " + std::to_string(offset + count) + ") of " +
                                        std::to_string(all.size() / n));
                for (UINT i = 0; i < count; ++i) std::copy(data + 4 * i, data + 4 * i + n, all.begin() + (offset + i) * n);
                p.SetValue(std::span<const float>(all));
            });
        }
        HRESULT GetFloatVector(float* data) override {
            return v_.set("GetFloatVector", v_.is(EffectParameterClass::Vector) && data, [&](EffectParameter& p) {
                std::vector<float> all = p.GetValueSingleArray();
                std::copy(all.begin(), all.begin() + p.ColumnCount(), data);
            });
        }
    };

    class MatrixView final : public View<ID3DX11EffectMatrixVariable> {
    public:
        using View::View;
        static fxport::Matrix of(const float* m) {
            return fxport::Matrix(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8], m[9], m[10], m[11], m[12], m[13], m[14], m[15]);
        }
        HRESULT SetMatrix(const float* data) override {
            return v_.set("SetMatrix", v_.is(EffectParameterClass::Matrix) && data, [&](EffectParameter& p) { p.SetValue(of(data)); });
        }
        HRESULT SetMatrixTranspose(const float* data) override {
            return v_.set("SetMatrixTranspose", v_.is(EffectParameterClass::Matrix) && data,
                          [&](EffectParameter& p) { p.SetValueTranspose(of(data)); });
        }
        HRESULT SetMatrixArray(const float* data, UINT offset, UINT count) override {
            return v_.set("SetMatrixArray", v_.is(EffectParameterClass::Matrix) && data, [&](EffectParameter& p) {
                const int elements = std::max(p.ElementCount(), 1);
                if (int(offset + count) > elements)
                    throw ArgumentError("elements [" + std::to_string(offset) + ", " + std::to_string(offset + count) + ") of " +
                                        std::to_string(elements));
                std::vector<fxport::Matrix> all = p.GetValueMatrixArray(elements);
                for (UINT i = 0; i < count; ++i) all[offset + i] = of(data + 16 * i);
                p.SetValue(std::span<const fxport::Matrix>(all));
            });
        }
        HRESULT GetMatrix(float* data) override {
            return v_.set("GetMatrix", v_.is(EffectParameterClass::Matrix) && data, [&](EffectParameter& p) {
                const fxport::Matrix m = p.GetValueMatrix();
                const float values[16] = {m.M11, m.M12, m.M13, m.M14, m.M21, m.M22, m.M23, m.M24,
                                          m.M31, m.M32, m.M33, m.M34, m.M41, m.M42, m.M43, m.M44};
                std::copy(values, values + 16, data);
            });
        }
    };

    class Resource final : public View<ID3DX11EffectShaderResourceVariable> {
    public:
        using View::View;
        HRESULT SetResource(ID3D11ShaderResourceView* view) override;
    };

    Effect11* owner_;
    EffectParameter* parameter_;
    Scalar scalar_;
    Vector vector_;
    MatrixView matrix_;
    Resource resource_;
};

class Pass final : public ID3DX11EffectPass {
public:
    Pass(Effect11* owner, fxport::EffectPass* pass, int technique, int index) : owner_(owner), pass_(pass), technique_(technique), index_(index) {}
    BOOL IsValid() override { return pass_ != nullptr; }
    HRESULT GetDesc(D3DX11_PASS_DESC* pDesc) override;
    HRESULT Apply(UINT Flags, ID3D11DeviceContext* pContext) override;

private:
    Effect11* owner_;
    fxport::EffectPass* pass_;
    int technique_, index_;
    std::string signature_;  // the pass's vertex shader as a blob CreateInputLayout takes
};

class Technique final : public ID3DX11EffectTechnique {
public:
    BOOL IsValid() override { return technique_ != nullptr; }
    HRESULT GetDesc(D3DX11_TECHNIQUE_DESC* pDesc) override {
        if (!technique_ || !pDesc) return fail(E_FAIL, "ID3DX11EffectTechnique::GetDesc: an invalid technique");
        *pDesc = D3DX11_TECHNIQUE_DESC{};
        pDesc->Name = technique_->Name().c_str();
        pDesc->Passes = UINT(passes.size());
        pDesc->Annotations = UINT(technique_->Annotations().size());
        return S_OK;
    }
    ID3DX11EffectPass* GetPassByIndex(UINT i) override { return i < passes.size() ? &passes[i] : invalidPass; }
    ID3DX11EffectPass* GetPassByName(LPCSTR name) override {
        if (technique_ && name)
            for (std::size_t i = 0; i < passes.size(); ++i)
                if (technique_->Passes[int(i)].Name() == name) return &passes[i];
        return invalidPass;
    }
    fxport::EffectTechnique* technique_ = nullptr;
    std::deque<Pass> passes;
    Pass* invalidPass = nullptr;
};

class Effect11 final : public ID3DX11Effect {
public:
    Effect11(Device* device, std::unique_ptr<fxport::Effect> effect) : device_(device), effect_(std::move(effect)), invalidPass_(this, nullptr, -1, -1) {
        device_->AddRef();  // the context may point at one of its passes: the device outlives it
        invalidTechnique_.invalidPass = &invalidPass_;
        for (int t = 0; t < effect_->Techniques.Count(); ++t) {
            Technique& technique = techniques_.emplace_back();
            technique.technique_ = effect_->Techniques[t];
            technique.invalidPass = &invalidPass_;
            for (int p = 0; p < technique.technique_->Passes.Count(); ++p)
                technique.passes.emplace_back(this, &technique.technique_->Passes[p], t, p);
        }
    }
    ~Effect11() override {
        device_->context().forgetEffect(this);
        effect_.reset();
        device_->Release();
    }
    ULONG AddRef() override { return ++references_; }
    ULONG Release() override {
        const ULONG left = --references_;
        if (left == 0) delete this;
        return left;
    }
    BOOL IsValid() override { return TRUE; }
    HRESULT GetDesc(D3DX11_EFFECT_DESC* pDesc) override {
        if (!pDesc) return E_INVALIDARG;
        *pDesc = D3DX11_EFFECT_DESC{};
        pDesc->Techniques = UINT(techniques_.size());
        pDesc->GlobalVariables = UINT(effect_->Parameters.Count());
        return S_OK;
    }
    ID3DX11EffectTechnique* GetTechniqueByIndex(UINT i) override { return i < techniques_.size() ? &techniques_[i] : &invalidTechnique_; }
    ID3DX11EffectTechnique* GetTechniqueByName(LPCSTR name) override {
        for (Technique& t : techniques_)
            if (name && t.technique_->Name() == name) return &t;
        return &invalidTechnique_;
    }
    ID3DX11EffectVariable* GetVariableByName(LPCSTR name) override {
        if (!name) return &invalidVariable_;
        auto it = variables_.find(name);
        if (it != variables_.end()) return it->second.get();
        EffectParameter* p = effect_->Parameters.find(name);
        if (!p) return &invalidVariable_;
        return variables_.emplace(name, std::make_unique<Variable>(this, p)).first->second.get();
    }
    ID3DX11EffectVariable* GetVariableBySemantic(LPCSTR semantic) override {
        for (EffectParameter& p : effect_->Parameters)
            if (semantic && iequal(p.Semantic(), semantic)) return GetVariableByName(p.Name().c_str());
        return &invalidVariable_;
    }

    Device& device() const { return *device_; }
    fxport::Effect& effect() const { return *effect_; }

private:
    static bool iequal(const std::string& a, const std::string& b) {
        return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) { return std::toupper(x) == std::toupper(y); });
    }
    Device* device_;
    std::unique_ptr<fxport::Effect> effect_;
    std::deque<Technique> techniques_;
    std::map<std::string, std::unique_ptr<Variable>> variables_;
    Variable invalidVariable_{this, nullptr};
    Technique invalidTechnique_;
    Pass invalidPass_;
    std::atomic<ULONG> references_{1};
};

HRESULT Variable::Resource::SetResource(ID3D11ShaderResourceView* view) {
    auto* srv = dynamic_cast<ShaderResourceView*>(view);
    if (view && (!srv || &srv->device() != &v_.owner()->device()))
        return fail(E_INVALIDARG, "SetResource: the view was not made by the effect's device");
    if (srv && !srv->sampled()) return fail(E_NOTIMPL, "SetResource: a view of a buffer; effect variables take texture views only in fxport");
    return v_.set("SetResource", v_.is(EffectParameterClass::Object), [&](EffectParameter& p) {
        p.SetValue(srv ? srv->sampled() : nullptr);
    });
}

HRESULT Pass::GetDesc(D3DX11_PASS_DESC* pDesc) {
    if (!pass_ || !pDesc) return fail(E_FAIL, "ID3DX11EffectPass::GetDesc: an invalid pass");
    return guarded("ID3DX11EffectPass::GetDesc", [&] {
        if (signature_.empty()) {
            // The pass's vertex shader alone, as a blob: what CreateInputLayout matches the layout against.
            const xlate::CompiledEffect& whole = owner_->effect().compiled();
            const xlate::Pass& pass = whole.techniques.at(std::size_t(technique_)).passes.at(std::size_t(index_));
            if (pass.vertexShader.shaders.empty()) return fail(E_FAIL, "ID3DX11EffectPass::GetDesc: pass '" + pass.name + "' has no vertex shader");
            xlate::CompiledEffect alone = whole;
            alone.techniques.clear();
            alone.shaders = {whole.shaders.at(std::size_t(pass.vertexShader.shaders[0]))};
            signature_ = shaderBlob(alone);
        }
        *pDesc = D3DX11_PASS_DESC{};
        pDesc->Name = pass_->Name().c_str();
        pDesc->Annotations = UINT(pass_->Annotations().size());
        pDesc->pIAInputSignature = reinterpret_cast<UINT8*>(signature_.data());
        pDesc->IAInputSignatureSize = signature_.size();
        return succeed();
    });
}

HRESULT Pass::Apply(UINT, ID3D11DeviceContext* pContext) {
    if (!pass_) return fail(E_FAIL, "ID3DX11EffectPass::Apply: an invalid pass (no such index or name)");
    auto* context = dynamic_cast<Context*>(pContext);
    if (!context || context != &owner_->device().context())
        return fail(E_INVALIDARG, "ID3DX11EffectPass::Apply: pContext is not the immediate context of the effect's device");
    // Applied once now so that compile errors of its technique surface here, then at each draw.
    return guarded("ID3DX11EffectPass::Apply", [&] {
        pass_->Apply();
        context->applyEffectPass(pass_, owner_);
        return succeed();
    });
}

Device* ourDevice(ID3D11Device* device) { return dynamic_cast<Device*>(device); }

HRESULT make(const char* call, ID3D11Device* pDevice, ID3DX11Effect** ppEffect, const std::function<std::unique_ptr<fxport::Effect>(GraphicsDevice&)>& load) {
    Device* device = ourDevice(pDevice);
    if (!device) return fail(E_INVALIDARG, std::string(call) + ": pDevice is not a device D3D11CreateDevice made");
    if (!ppEffect) return fail(E_INVALIDARG, std::string(call) + ": ppEffect is null");
    try {
        *ppEffect = new Effect11(device, load(device->core()));
        return succeed();
    } catch (const xlate::CompileError& e) {
        std::string text;
        for (const auto& d : e.diagnostics()) text += "\n" + d.format();
        return fail(E_FAIL, std::string(call) + ":" + text);
    } catch (const std::exception& e) {
        return fail(E_FAIL, std::string(call) + ": " + e.what());
    }
}

}  // namespace

// core_access.h: Effect11 is the only ID3DX11Effect there is.
Effect& CoreEffectOf(ID3DX11Effect& effect) { return static_cast<Effect11&>(effect).effect(); }

HRESULT D3DX11CreateEffectFromMemory(const void* pData, SIZE_T DataLength, UINT, ID3D11Device* pDevice, ID3DX11Effect** ppEffect, LPCSTR) {
    std::string error;
    BlobKind kind = BlobKind::Shader;
    auto compiled = effectFromBytecode(pData, DataLength, error, &kind);
    if (!compiled) return fail(E_INVALIDARG, "D3DX11CreateEffectFromMemory: " + error);
    if (kind != BlobKind::Effect)
        return fail(E_INVALIDARG, "D3DX11CreateEffectFromMemory: the blob holds one shader, not an effect (compile the .fx with an fx_5_0 or fx_4_0 target)");
    return make("D3DX11CreateEffectFromMemory", pDevice, ppEffect,
                [&](GraphicsDevice& core) { return std::make_unique<fxport::Effect>(core, *compiled); });
}

// The .fx file compiled as D3DCompileFromFile compiles it for fx_5_0 (FX11's rules: an effect may
// have no technique), then made into the effect as from memory.
HRESULT D3DX11CreateEffectFromFile(LPCSTR pFileName, UINT, ID3D11Device* pDevice, ID3DX11Effect** ppEffect) {
    const char* call = "D3DX11CreateEffectFromFile";
    if (!pFileName) return fail(E_INVALIDARG, std::string(call) + ": pFileName is null");
    ComPtr<ID3DBlob> code;
    if (HRESULT hr = D3DCompileFromFile(pFileName, nullptr, nullptr, nullptr, "fx_5_0", 0, 0, code.GetAddressOf(), nullptr); FAILED(hr))
        return fail(hr, std::string(call) + " (fx_5_0): " + GetLastErrorMessage());
    return D3DX11CreateEffectFromMemory(code->GetBufferPointer(), code->GetBufferSize(), 0, pDevice, ppEffect, pFileName);
}

HRESULT D3DX11CreateEffectFromFile(const wchar_t* pFileName, UINT flags, ID3D11Device* pDevice, ID3DX11Effect** ppEffect) {
    if (!pFileName) return fail(E_INVALIDARG, "D3DX11CreateEffectFromFile: pFileName is null");
    return D3DX11CreateEffectFromFile(narrowPath(pFileName).c_str(), flags, pDevice, ppEffect);
}

}  // namespace fxport::d3d11
