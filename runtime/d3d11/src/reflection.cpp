// D3DReflect: ID3D11ShaderReflection over a compiled blob: constant buffers with their variables at
// D3D's packed offsets, bound resources with their b#/t#/s# registers (shader_bindings.h), the
// vertex shader's input signature. Sub-objects live in the reflection object, as in D3D.
#include <algorithm>
#include <cctype>
#include <deque>
#include <memory>

#include "d3d11_impl.h"
#include "reflection_type.h"

namespace fxport::d3d11 {

namespace {

std::pair<std::string, UINT> splitSemantic(const std::string& s) {
    std::size_t digits = s.size();
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(s[digits - 1]))) --digits;
    return {s.substr(0, digits), digits < s.size() ? UINT(std::stoul(s.substr(digits))) : 0u};
}

class ReflectionVariable final : public ID3D11ShaderReflectionVariable {
public:
    D3D11_SHADER_VARIABLE_DESC desc;
    std::string name;
    ReflectionType type;
    bool valid = false;
    HRESULT GetDesc(D3D11_SHADER_VARIABLE_DESC* p) override {
        if (!valid || !p) return E_FAIL;
        *p = desc;
        p->Name = name.c_str();
        return S_OK;
    }
    ID3D11ShaderReflectionType* GetType() override { return &type; }
};

class ReflectionBuffer final : public ID3D11ShaderReflectionConstantBuffer {
public:
    D3D11_SHADER_BUFFER_DESC desc;
    std::string name;
    std::deque<ReflectionVariable> variables;
    ReflectionVariable* invalid = nullptr;
    bool valid = false;
    HRESULT GetDesc(D3D11_SHADER_BUFFER_DESC* p) override {
        if (!valid || !p) return E_FAIL;
        *p = desc;
        p->Name = name.c_str();
        return S_OK;
    }
    ID3D11ShaderReflectionVariable* GetVariableByIndex(UINT i) override {
        return valid && i < variables.size() ? &variables[i] : invalid;
    }
    ID3D11ShaderReflectionVariable* GetVariableByName(LPCSTR n) override {
        for (auto& v : variables)
            if (n && v.name == n) return &v;
        return invalid;
    }
};

// D3D11_SHVER_PIXEL_SHADER 0, VERTEX 1, GEOMETRY 2, HULL 3, DOMAIN 4, COMPUTE 5.
UINT shaderVersionType(xlate::ShaderStage stage) {
    switch (stage) {
    case xlate::ShaderStage::Pixel: return 0;
    case xlate::ShaderStage::Vertex: return 1;
    case xlate::ShaderStage::Geometry: return 2;
    case xlate::ShaderStage::Hull: return 3;
    case xlate::ShaderStage::Domain: return 4;
    case xlate::ShaderStage::Compute: return 5;
    }
    return 1;
}

class Reflection final : public ID3D11ShaderReflection {
public:
    Reflection(std::shared_ptr<const xlate::CompiledEffect> effect, int shader) : effect_(std::move(effect)), shader_(shader) {
        bindings_ = bindingsOf(*effect_, shader);
        const xlate::CompiledShader& s = effect_->shaders[std::size_t(shader)];
        creator_ = "fxport (" + s.profile.name + ")";
        for (const CbufferBinding& c : bindings_.cbuffers) addBuffer(c);
        for (const auto& t : bindings_.samplers) resources_.push_back({t.name, D3D_SIT_SAMPLER, UINT(t.slot), D3D_SRV_DIMENSION_UNKNOWN});
        for (const auto& t : bindings_.textures)
            resources_.push_back({t.name, D3D_SIT_TEXTURE, UINT(t.slot),
                                  t.kind == xlate::TextureKind::TextureCube ? D3D_SRV_DIMENSION_TEXTURECUBE
                                  : t.kind == xlate::TextureKind::Texture3D ? D3D_SRV_DIMENSION_TEXTURE3D
                                  : t.kind == xlate::TextureKind::Texture1D ? D3D_SRV_DIMENSION_TEXTURE1D
                                                                             : D3D_SRV_DIMENSION_TEXTURE2D});  // xlate does not mark arrays
        for (const CbufferBinding& c : bindings_.cbuffers) resources_.push_back({c.name, D3D_SIT_CBUFFER, UINT(c.slot), D3D_SRV_DIMENSION_UNKNOWN});
        // Buffers and RWTexture2Ds (xlate's storage list; a ByteAddressBuffer reads as a structured
        // buffer of 4-byte elements: xlate does not tell them apart).
        for (const xlate::StorageBinding& b : s.storage) {
            const bool uav = b.registerClass == 'u', image = b.kind == xlate::StorageKind::Image;
            const bool typed = b.kind == xlate::StorageKind::TexelBuffer || b.kind == xlate::StorageKind::ImageBuffer;  // (RW)Buffer<T>
            const D3D_SHADER_INPUT_TYPE type = image || (typed && uav) ? D3D_SIT_UAV_RWTYPED
                                               : typed                 ? D3D_SIT_TEXTURE
                                               : uav                   ? D3D_SIT_UAV_RWSTRUCTURED
                                                                       : D3D_SIT_STRUCTURED;
            resources_.push_back({b.name, type, UINT(b.slot), image ? D3D_SRV_DIMENSION_TEXTURE2D : D3D_SRV_DIMENSION_BUFFER,
                                  image || typed ? 0u : UINT(b.stride)});
        }
        std::vector<const xlate::VertexInput*> inputs;
        for (const auto& in : s.inputs) inputs.push_back(&in);
        std::sort(inputs.begin(), inputs.end(), [](auto* a, auto* b) { return a->location < b->location; });
        for (const auto* in : inputs) {
            auto [name, index] = splitSemantic(in->semantic);
            inputs_.push_back({name, index, UINT(in->location), in->isInteger ? D3D_REGISTER_COMPONENT_SINT32 : D3D_REGISTER_COMPONENT_FLOAT32,
                               UINT8((1u << in->components) - 1u)});
        }
        addOutputs(s);
        invalidBuffer_.invalid = &invalidVariable_;
    }
    ULONG AddRef() override { return ++references_; }
    ULONG Release() override {
        const ULONG left = --references_;
        if (left == 0) delete this;
        return left;
    }
    HRESULT GetDesc(D3D11_SHADER_DESC* p) override {
        if (!p) return E_INVALIDARG;
        const xlate::ShaderProfile& profile = effect_->shaders[std::size_t(shader_)].profile;
        const UINT type = shaderVersionType(profile.stage);
        *p = D3D11_SHADER_DESC{};
        p->Version = type << 16 | UINT(profile.major) << 4 | UINT(profile.minor);
        p->Creator = creator_.c_str();
        p->ConstantBuffers = UINT(buffers_.size());
        p->BoundResources = UINT(resources_.size());
        p->InputParameters = UINT(inputs_.size());
        p->OutputParameters = UINT(outputs_.size());
        return S_OK;
    }
    ID3D11ShaderReflectionConstantBuffer* GetConstantBufferByIndex(UINT i) override {
        return i < buffers_.size() ? &buffers_[i] : &invalidBuffer_;
    }
    ID3D11ShaderReflectionConstantBuffer* GetConstantBufferByName(LPCSTR n) override {
        for (auto& b : buffers_)
            if (n && b.name == n) return &b;
        return &invalidBuffer_;
    }
    ID3D11ShaderReflectionVariable* GetVariableByName(LPCSTR n) override {
        for (auto& b : buffers_)
            for (auto& v : b.variables)
                if (n && v.name == n) return &v;
        return &invalidVariable_;
    }
    HRESULT GetResourceBindingDesc(UINT i, D3D11_SHADER_INPUT_BIND_DESC* p) override {
        if (!p || i >= resources_.size()) return fail(E_INVALIDARG, "GetResourceBindingDesc: index " + std::to_string(i) + " of " + std::to_string(resources_.size()));
        const Resource& r = resources_[i];
        *p = D3D11_SHADER_INPUT_BIND_DESC{};
        p->Name = r.name.c_str();
        p->Type = r.type;
        p->BindPoint = r.slot;
        p->Dimension = r.dimension;
        p->NumSamples = r.stride;
        return S_OK;
    }
    HRESULT GetResourceBindingDescByName(LPCSTR n, D3D11_SHADER_INPUT_BIND_DESC* p) override {
        for (std::size_t i = 0; i < resources_.size(); ++i)
            if (n && resources_[i].name == n) return GetResourceBindingDesc(UINT(i), p);
        return fail(E_INVALIDARG, std::string("GetResourceBindingDescByName: the shader binds nothing named '") + (n ? n : "") + "'");
    }
    UINT GetThreadGroupSize(UINT* x, UINT* y, UINT* z) override {
        const xlate::CompiledShader& s = effect_->shaders[std::size_t(shader_)];
        const bool compute = s.profile.stage == xlate::ShaderStage::Compute;
        const UINT size[3] = {compute ? UINT(s.threadGroupSize[0]) : 0u, compute ? UINT(s.threadGroupSize[1]) : 0u,
                              compute ? UINT(s.threadGroupSize[2]) : 0u};
        if (x) *x = size[0];
        if (y) *y = size[1];
        if (z) *z = size[2];
        return size[0] * size[1] * size[2];
    }
    HRESULT GetInputParameterDesc(UINT i, D3D11_SIGNATURE_PARAMETER_DESC* p) override {
        return signatureDesc("GetInputParameterDesc", inputs_, i, p);
    }
    HRESULT GetOutputParameterDesc(UINT i, D3D11_SIGNATURE_PARAMETER_DESC* p) override {
        return signatureDesc("GetOutputParameterDesc", outputs_, i, p);
    }

private:
    struct Resource {
        std::string name;
        D3D_SHADER_INPUT_TYPE type;
        UINT slot;
        D3D_SRV_DIMENSION dimension;
        UINT stride = 0;  // structured buffers
    };
    struct Input {
        std::string name;
        UINT index;
        UINT registerIndex;
        D3D_REGISTER_COMPONENT_TYPE type;
        UINT8 mask;
        D3D_NAME systemValue = D3D_NAME_UNDEFINED;
    };

    static HRESULT signatureDesc(const char* call, const std::vector<Input>& list, UINT i, D3D11_SIGNATURE_PARAMETER_DESC* p) {
        if (!p || i >= list.size()) return fail(E_INVALIDARG, std::string(call) + ": index " + std::to_string(i) + " of " + std::to_string(list.size()));
        const Input& in = list[i];
        *p = D3D11_SIGNATURE_PARAMETER_DESC{};
        p->SemanticName = in.name.c_str();
        p->SemanticIndex = in.index;
        p->Register = in.registerIndex;
        p->SystemValueType = in.systemValue;
        p->ComponentType = in.type;
        p->Mask = in.mask;
        p->ReadWriteMask = in.mask;
        return S_OK;
    }

    // What the stage writes, from xlate's reflection: render targets and depth of a pixel shader;
    // the position, the user semantics (at their GL locations) and the clip distances (four to a
    // register, as fxc packs them) of the others.
    void addOutputs(const xlate::CompiledShader& s) {
        using xlate::ShaderStage;
        const ShaderStage stage = s.profile.stage;
        if (stage == ShaderStage::Compute) return;
        if (stage == ShaderStage::Pixel) {
            for (int t = 0; t < s.outputTargets; ++t)
                outputs_.push_back({"SV_Target", UINT(t), UINT(t), D3D_REGISTER_COMPONENT_FLOAT32, 0xF, D3D_NAME_TARGET});
            if (s.writesDepth) outputs_.push_back({"SV_Depth", 0, 0xFFFFFFFFu, D3D_REGISTER_COMPONENT_FLOAT32, 0x1, D3D_NAME_DEPTH});
            return;
        }
        if (stage != ShaderStage::Hull) outputs_.push_back({"SV_Position", 0, 0, D3D_REGISTER_COMPONENT_FLOAT32, 0xF, D3D_NAME_POSITION});
        for (const xlate::Varying& v : s.varyingOutputs) {
            auto [name, index] = splitSemantic(v.semantic);
            outputs_.push_back({name, UINT(index), UINT(v.location), D3D_REGISTER_COMPONENT_UNKNOWN, 0});
        }
        UINT next = 0;  // the registers after the others
        for (const Input& o : outputs_) next = std::max(next, o.registerIndex + 1);
        for (int first = 0; first < s.clipDistances; first += 4) {
            const int count = std::min(4, s.clipDistances - first);
            outputs_.push_back({"SV_ClipDistance", UINT(first / 4), next++, D3D_REGISTER_COMPONENT_FLOAT32, UINT8((1u << count) - 1u),
                                D3D_NAME_CLIP_DISTANCE});
        }
    }

    void addBuffer(const CbufferBinding& c) {
        ReflectionBuffer& b = buffers_.emplace_back();
        b.valid = true;
        b.name = c.name;
        b.desc.Size = UINT(c.size);
        b.invalid = &invalidVariable_;
        const xlate::CompiledShader& s = effect_->shaders[std::size_t(shader_)];
        for (const PackedVariable& v : packCbuffer(*effect_, c.block)) {
            const xlate::Parameter& p = effect_->parameters[std::size_t(v.parameter)];
            ReflectionVariable& r = b.variables.emplace_back();
            r.valid = true;
            r.name = p.name;
            r.desc.StartOffset = UINT(v.offset);
            r.desc.Size = UINT(v.size);
            r.desc.uFlags = std::find(s.parametersRead.begin(), s.parametersRead.end(), v.parameter) != s.parametersRead.end() ? D3D_SVF_USED : 0;
            r.type = ReflectionType(p, 0);
        }
        b.desc.Variables = UINT(b.variables.size());
    }

    std::shared_ptr<const xlate::CompiledEffect> effect_;
    int shader_;
    ShaderBindings bindings_;
    std::string creator_;
    std::deque<ReflectionBuffer> buffers_;
    std::vector<Resource> resources_;
    std::vector<Input> inputs_;
    std::vector<Input> outputs_;
    ReflectionBuffer invalidBuffer_;
    ReflectionVariable invalidVariable_;
    std::atomic<ULONG> references_{1};
};

}  // namespace

HRESULT D3DReflect(LPCVOID pSrcData, SIZE_T SrcDataSize, ID3D11ShaderReflection** ppReflector) {
    if (!ppReflector) return fail(E_INVALIDARG, "D3DReflect: ppReflector is null");
    std::string error;
    auto effect = effectFromBytecode(pSrcData, SrcDataSize, error);
    if (!effect) return fail(E_INVALIDARG, "D3DReflect: " + error);
    if (effect->shaders.empty()) return fail(E_INVALIDARG, "D3DReflect: the blob holds no shader");
    try {
        *ppReflector = new Reflection(effect, 0);
    } catch (const std::exception& e) {
        return fail(E_FAIL, std::string("D3DReflect: ") + e.what());
    }
    return succeed();
}

}  // namespace fxport::d3d11
