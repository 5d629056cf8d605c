// D3D11CreateDevice and the device's Create* calls for shaders, input layouts and state objects
// (resources.cpp and views.cpp make resources and views). The device owns the device core (an
// XNA GraphicsDevice made headless, with D3D's defaults where XNA's differ) and the immediate
// context.
#include <algorithm>

#include "context.h"
#include "device/vertex_input.h"
#include "dxgi_impl.h"
#include "guarded.h"

namespace fxport::d3d11 {

namespace {

PresentationParameters coreParameters() {
    PresentationParameters p;
    // The core's back buffer is never shown: D3D11 renders into textures (no swap chain yet).
    p.BackBufferWidth = 1;
    p.BackBufferHeight = 1;
    p.DepthStencilFormat = DepthFormat::None;
    // D3D keeps a target's contents when it is bound again (XNA's DiscardContents clears it).
    p.RenderTargetUsage = RenderTargetUsage::PreserveContents;
    // Each draw is exactly what was asked; the core's compute-pass rewrite stays off.
    p.Optimizations.ComputePasses = false;
    return p;
}

// The shader of `stage` in a compiled blob (D3DCompile makes one shader per blob).
int shaderOfStage(const xlate::CompiledEffect& e, xlate::ShaderStage stage) {
    for (std::size_t i = 0; i < e.shaders.size(); ++i)
        if (e.shaders[i].profile.stage == stage) return int(i);
    return -1;
}

const char* stageName(xlate::ShaderStage s) {
    switch (s) {
    case xlate::ShaderStage::Vertex: return "vertex";
    case xlate::ShaderStage::Pixel: return "pixel";
    case xlate::ShaderStage::Geometry: return "geometry";
    case xlate::ShaderStage::Hull: return "hull";
    case xlate::ShaderStage::Domain: return "domain";
    case xlate::ShaderStage::Compute: return "compute";
    }
    return "?";
}

template <class Shader, class Interface>
HRESULT createShader(Device* device, const void* bytecode, SIZE_T length, xlate::ShaderStage stage, const char* call, Interface** out) {
    if (!bytecode || length == 0) return fail(E_INVALIDARG, std::string(call) + ": pShaderBytecode is null or empty");
    std::string error;
    BlobKind kind = BlobKind::Shader;
    std::shared_ptr<const xlate::CompiledEffect> effect = effectFromBytecode(bytecode, length, error, &kind);
    if (!effect) return fail(E_INVALIDARG, std::string(call) + ": " + error);
    if (kind != BlobKind::Shader)
        return fail(E_INVALIDARG, std::string(call) + ": the bytecode is a whole effect (an fx_* target); make it with D3DX11CreateEffectFromMemory");
    const int index = shaderOfStage(*effect, stage);
    if (index < 0) {
        const std::string held = effect->shaders.empty() ? std::string("no shader") : "a " + effect->shaders[0].profile.name + " shader";
        return fail(E_INVALIDARG, std::string(call) + ": the bytecode holds " + held + ", not a " + stageName(stage) + " shader");
    }
    return guarded(call, [&] {
        ShaderBindings bindings = bindingsOf(*effect, index);
        if (std::string mismatch = layoutMismatch(*effect, bindings); !mismatch.empty())
            return fail(E_FAIL, std::string(call) + ": " + mismatch);
        const xlate::CompiledShader& s = effect->shaders[std::size_t(index)];
        const std::string label = effect->sourcePath + ": " + s.entryPoint + " (" + s.profile.name + ")";
        auto code = std::make_unique<core::ShaderCode>(device->core(), effect, index, label);
        if (out) *out = new Shader(device, std::move(code), std::move(bindings));
        return succeed();
    });
}

}  // namespace

Device::Device() : core_(std::make_unique<GraphicsDevice>(coreParameters())) { context_ = std::make_unique<Context>(this); }

Device::~Device() {
    context_.reset();  // releases what it binds while the core is alive
    core_.reset();
}

ULONG Device::Release() {
    const ULONG left = --references_;
    if (left == 0) delete this;
    return left;
}

void Device::GetImmediateContext(ID3D11DeviceContext** pp) {
    if (!pp) return;
    AddRef();
    *pp = context_.get();
}

HRESULT Device::CreateVertexShader(const void* b, SIZE_T n, ID3D11ClassLinkage* linkage, ID3D11VertexShader** pp) {
    if (linkage) return fail(E_NOTIMPL, "CreateVertexShader: class linkage (dynamic shader linking) is not supported");
    return createShader<VertexShader>(this, b, n, xlate::ShaderStage::Vertex, "CreateVertexShader", pp);
}
HRESULT Device::CreatePixelShader(const void* b, SIZE_T n, ID3D11ClassLinkage* linkage, ID3D11PixelShader** pp) {
    if (linkage) return fail(E_NOTIMPL, "CreatePixelShader: class linkage (dynamic shader linking) is not supported");
    return createShader<PixelShader>(this, b, n, xlate::ShaderStage::Pixel, "CreatePixelShader", pp);
}
HRESULT Device::CreateGeometryShader(const void* b, SIZE_T n, ID3D11ClassLinkage* linkage, ID3D11GeometryShader** pp) {
    if (linkage) return fail(E_NOTIMPL, "CreateGeometryShader: class linkage (dynamic shader linking) is not supported");
    return createShader<GeometryShader>(this, b, n, xlate::ShaderStage::Geometry, "CreateGeometryShader", pp);
}
HRESULT Device::CreateHullShader(const void* b, SIZE_T n, ID3D11ClassLinkage* linkage, ID3D11HullShader** pp) {
    if (linkage) return fail(E_NOTIMPL, "CreateHullShader: class linkage (dynamic shader linking) is not supported");
    return createShader<HullShader>(this, b, n, xlate::ShaderStage::Hull, "CreateHullShader", pp);
}
HRESULT Device::CreateDomainShader(const void* b, SIZE_T n, ID3D11ClassLinkage* linkage, ID3D11DomainShader** pp) {
    if (linkage) return fail(E_NOTIMPL, "CreateDomainShader: class linkage (dynamic shader linking) is not supported");
    return createShader<DomainShader>(this, b, n, xlate::ShaderStage::Domain, "CreateDomainShader", pp);
}
HRESULT Device::CreateComputeShader(const void* b, SIZE_T n, ID3D11ClassLinkage* linkage, ID3D11ComputeShader** pp) {
    if (linkage) return fail(E_NOTIMPL, "CreateComputeShader: class linkage (dynamic shader linking) is not supported");
    return createShader<ComputeShader>(this, b, n, xlate::ShaderStage::Compute, "CreateComputeShader", pp);
}

HRESULT Device::CreateInputLayout(const D3D11_INPUT_ELEMENT_DESC* descs, UINT count, const void* bytecode, SIZE_T length,
                                  ID3D11InputLayout** pp) {
    const char* call = "CreateInputLayout";
    if (count > 0 && !descs) return fail(E_INVALIDARG, "CreateInputLayout: pInputElementDescs is null");
    if (count > D3D11_IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT)
        return fail(E_INVALIDARG, "CreateInputLayout: NumElements = " + std::to_string(count) + " (at most 32)");
    std::string error;
    std::shared_ptr<const xlate::CompiledEffect> effect = effectFromBytecode(bytecode, length, error);
    if (!effect) return fail(E_INVALIDARG, std::string(call) + ": " + error);
    const int vs = shaderOfStage(*effect, xlate::ShaderStage::Vertex);
    if (vs < 0) return fail(E_INVALIDARG, "CreateInputLayout: the bytecode is not a vertex shader's (it has no input signature)");
    std::vector<InputLayout::Slot> slots;
    std::vector<std::string> semantics;
    std::vector<UINT> offsets(D3D11_IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT, 0);  // each slot's next aligned offset
    for (UINT i = 0; i < count; ++i) {
        const D3D11_INPUT_ELEMENT_DESC& d = descs[i];
        const std::string at = "CreateInputLayout: pInputElementDescs[" + std::to_string(i) + "].";
        if (!d.SemanticName || !*d.SemanticName) return fail(E_INVALIDARG, at + "SemanticName is null or empty");
        VertexFormat format;
        if (!vertexFormat(d.Format, format))
            return fail(d.Format == DXGI_FORMAT_UNKNOWN ? E_INVALIDARG : E_NOTIMPL,
                        at + "Format = " + formatName(d.Format) + " (" + std::to_string(d.Format) + "): not a vertex format fxport supports");
        if (d.InputSlot >= D3D11_IA_VERTEX_INPUT_RESOURCE_SLOT_COUNT)
            return fail(E_INVALIDARG, at + "InputSlot = " + std::to_string(d.InputSlot) + " (0..31)");
        if (d.InputSlotClass != D3D11_INPUT_PER_VERTEX_DATA && d.InputSlotClass != D3D11_INPUT_PER_INSTANCE_DATA)
            return fail(E_INVALIDARG, at + "InputSlotClass = " + std::to_string(d.InputSlotClass) + " (PER_VERTEX_DATA 0 or PER_INSTANCE_DATA 1)");
        const bool perInstance = d.InputSlotClass == D3D11_INPUT_PER_INSTANCE_DATA;
        if (!perInstance && d.InstanceDataStepRate != 0)
            return fail(E_INVALIDARG, at + "InstanceDataStepRate = " + std::to_string(d.InstanceDataStepRate) + " with PER_VERTEX_DATA (must be 0)");
        if (perInstance && d.InstanceDataStepRate == 0)
            return fail(E_NOTIMPL, at + "InstanceDataStepRate = 0 with PER_INSTANCE_DATA: fxport steps instance data at least once per instance");
        if (slots.size() <= d.InputSlot) slots.resize(d.InputSlot + 1);
        InputLayout::Slot& slot = slots[d.InputSlot];
        const UINT rate = perInstance ? d.InstanceDataStepRate : 0;
        if (!slot.elements.empty() && slot.instanceStepRate != rate)
            return fail(E_INVALIDARG, at + "InputSlotClass/InstanceDataStepRate differ from an earlier element of InputSlot " +
                                          std::to_string(d.InputSlot) + " (a slot steps one way)");
        slot.instanceStepRate = rate;
        UINT& offset = offsets[d.InputSlot];
        if (d.AlignedByteOffset != D3D11_APPEND_ALIGNED_ELEMENT) offset = d.AlignedByteOffset;
        // D3D aligns an element to its component size (4 bytes for R32 and packed formats, 2 for R16, 1 for R8).
        const UINT align = UINT(vertexFormatSize(format) / (isPackedVertexComponent(format.component) ? 1 : format.count));
        if (offset % align != 0)
            return fail(E_INVALIDARG, at + "AlignedByteOffset = " + std::to_string(offset) + " (must be a multiple of " + std::to_string(align) +
                                          ", the format's component size)");
        // D3D matches elements to the shader's inputs by name (any name, case-insensitive) and index.
        const std::string semantic = vertexSemantic(d.SemanticName, int(d.SemanticIndex));
        if (std::find(semantics.begin(), semantics.end(), semantic) != semantics.end())
            return fail(E_INVALIDARG, at + "SemanticName/SemanticIndex = \"" + std::string(d.SemanticName) + "\"/" +
                                          std::to_string(d.SemanticIndex) + " appears twice");
        semantics.push_back(semantic);
        for (const xlate::VertexInput& input : effect->shaders[std::size_t(vs)].inputs)
            if (feedsInput(semantic, input))
                if (HRESULT hr = readAsInputReads(format, input.isInteger, d.Format, at); FAILED(hr)) return hr;
        slot.elements.push_back(core::StreamElement{semantic, int(offset), format});
        offset += UINT(vertexFormatSize(format));
    }
    // D3D's rule: every input of the shader's signature is in the layout (by name and index).
    for (const xlate::VertexInput& input : effect->shaders[std::size_t(vs)].inputs) {
        const bool position = input.semantic.rfind("SV_POSITION", 0) == 0;
        if (input.semantic.rfind("SV_", 0) == 0 && !position) continue;  // system values need no element
        const bool fed = std::any_of(semantics.begin(), semantics.end(), [&](const std::string& e) { return feedsInput(e, input); });
        if (!fed)
            return fail(E_INVALIDARG, "CreateInputLayout: the vertex shader's input " + input.semantic +
                                          " has no element in the layout (semantics match by name and index)");
    }
    if (pp) *pp = new InputLayout(this, std::move(slots));
    return succeed();
}

template <class State, class Interface, class Desc, class Core>
HRESULT createState(Device* device, const Desc* desc, Interface** pp, HRESULT (*decode)(const Desc&, Core&), const char* call) {
    if (!desc) return fail(E_INVALIDARG, std::string(call) + ": the description is null");
    Core decoded;
    if (HRESULT hr = decode(*desc, decoded); FAILED(hr)) return hr;
    if (pp) *pp = new State(device, *desc, decoded);
    return succeed();
}

HRESULT Device::CreateSamplerState(const D3D11_SAMPLER_DESC* d, ID3D11SamplerState** pp) {
    return createState<SamplerState>(this, d, pp, &decodeSampler, "CreateSamplerState");
}
HRESULT Device::CreateBlendState(const D3D11_BLEND_DESC* d, ID3D11BlendState** pp) {
    return createState<BlendState>(this, d, pp, &decodeBlend, "CreateBlendState");
}
HRESULT Device::CreateRasterizerState(const D3D11_RASTERIZER_DESC* d, ID3D11RasterizerState** pp) {
    return createState<RasterizerState>(this, d, pp, &decodeRasterizer, "CreateRasterizerState");
}
HRESULT Device::CreateDepthStencilState(const D3D11_DEPTH_STENCIL_DESC* d, ID3D11DepthStencilState** pp) {
    return createState<DepthStencilState>(this, d, pp, &decodeDepthStencil, "CreateDepthStencilState");
}

HRESULT D3D11CreateDevice(void* pAdapter, D3D_DRIVER_TYPE DriverType, void* Software, UINT Flags, const D3D_FEATURE_LEVEL* pFeatureLevels,
                          UINT FeatureLevels, UINT SDKVersion, ID3D11Device** ppDevice, D3D_FEATURE_LEVEL* pFeatureLevel,
                          ID3D11DeviceContext** ppImmediateContext) {
    if (Software) return fail(E_INVALIDARG, "D3D11CreateDevice: Software must be null (fxport has one GL driver)");
    // An adapter can only be the one IDXGIFactory::EnumAdapters gives (the GL driver's GPU); D3D's rule for it:
    if (pAdapter && DriverType != D3D_DRIVER_TYPE_UNKNOWN)
        return fail(E_INVALIDARG, "D3D11CreateDevice: DriverType = " + std::to_string(DriverType) + " with an adapter (it must be UNKNOWN)");
    if (DriverType == D3D_DRIVER_TYPE_NULL || DriverType > D3D_DRIVER_TYPE_WARP)
        return fail(E_INVALIDARG, "D3D11CreateDevice: DriverType = " + std::to_string(DriverType) + " (HARDWARE, WARP, REFERENCE or UNKNOWN)");
    if (SDKVersion != D3D11_SDK_VERSION)
        return fail(E_INVALIDARG, "D3D11CreateDevice: SDKVersion = " + std::to_string(SDKVersion) + " (D3D11_SDK_VERSION is 7)");
    if (pFeatureLevels && FeatureLevels > 0) {
        const bool any = std::any_of(pFeatureLevels, pFeatureLevels + FeatureLevels, [](D3D_FEATURE_LEVEL l) { return l <= D3D_FEATURE_LEVEL_11_0; });
        if (!any) return fail(E_INVALIDARG, "D3D11CreateDevice: none of pFeatureLevels is 11_0 or below");
    }
    if (pFeatureLevel) *pFeatureLevel = D3D_FEATURE_LEVEL_11_0;
    if (!ppDevice && !ppImmediateContext) return S_FALSE;  // D3D: the arguments are valid
    return guarded("D3D11CreateDevice", [&] {
        auto* device = new Device();
        device->creationFlags = Flags;
        if (ppImmediateContext) device->GetImmediateContext(ppImmediateContext);
        if (ppDevice) *ppDevice = device;
        else device->Release();  // the context holds it
        return succeed();
    });
}

}  // namespace fxport::d3d11
