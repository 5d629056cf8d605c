// The D3D11 session's shaders, constants, inputs, draws and dispatches (see d3d11_session.h).
#include "d3d11_session.h"

#include <cstring>
#include <type_traits>

#include "section_compiler.h"

namespace conformance {

using namespace fxport::d3d11;

namespace {

// Constant buffer 0 is D3D11's largest (4096 registers): a shader reads 0 past the uniforms given,
// as D3D reads 0 past the end of a smaller buffer, and no cbuffer outgrows it.
constexpr UINT kConstantBytes = 4096 * 16;

// A front-end call that failed: what fxport does not implement (E_NOTIMPL) skips, the rest fail.
// The front end's message names the call; `what` says what the runner was making.
void check(HRESULT hr, const std::string& what) {
    const std::string message = what.empty() ? GetLastErrorMessage() : what + ": " + GetLastErrorMessage();
    if (hr == E_NOTIMPL) throw Unsupported(message);
    if (FAILED(hr)) throw std::runtime_error(message);
}

// A void context call (a draw) that did nothing leaves its reason in GetLastErrorMessage().
void checkNoMessage(const char* call) {
    const std::string message = GetLastErrorMessage();
    if (!message.empty()) throw std::runtime_error(std::string(call) + " did nothing: " + message);
}

// The first error line of a D3DCompile error blob.
std::string firstError(ID3DBlob* errors) {
    if (!errors) return GetLastErrorMessage();
    std::string text(static_cast<const char*>(errors->GetBufferPointer()), errors->GetBufferSize());
    std::size_t at = text.find("error");
    std::size_t start = at == std::string::npos ? 0 : text.rfind('\n', at);
    start = start == std::string::npos ? 0 : start + (at != std::string::npos && start < at ? 1 : 0);
    return text.substr(start, text.find('\n', start) - start);
}

// The context's Set calls of one stage.
struct StageCalls {
    void (ID3D11DeviceContext::*constants)(UINT, UINT, ID3D11Buffer* const*);
    void (ID3D11DeviceContext::*views)(UINT, UINT, ID3D11ShaderResourceView* const*);
    void (ID3D11DeviceContext::*samplers)(UINT, UINT, ID3D11SamplerState* const*);
};
StageCalls callsOf(Stage stage) {
    using C = ID3D11DeviceContext;
    switch (stage) {
    case Stage::Vertex: return {&C::VSSetConstantBuffers, &C::VSSetShaderResources, &C::VSSetSamplers};
    case Stage::Geometry: return {&C::GSSetConstantBuffers, &C::GSSetShaderResources, &C::GSSetSamplers};
    case Stage::Hull: return {&C::HSSetConstantBuffers, &C::HSSetShaderResources, &C::HSSetSamplers};
    case Stage::Domain: return {&C::DSSetConstantBuffers, &C::DSSetShaderResources, &C::DSSetSamplers};
    case Stage::Compute: return {&C::CSSetConstantBuffers, &C::CSSetShaderResources, &C::CSSetSamplers};
    default: return {&C::PSSetConstantBuffers, &C::PSSetShaderResources, &C::PSSetSamplers};
    }
}

// The objects of `slots` as an array indexed by slot (null in the gaps).
template <class T>
std::vector<T*> bySlot(const std::map<int, ComPtr<T>>& slots) {
    std::vector<T*> out(slots.empty() ? 0 : std::size_t(slots.rbegin()->first + 1), nullptr);
    for (const auto& [slot, object] : slots)
        if (slot >= 0) out[std::size_t(slot)] = object.Get();
    return out;
}

const Stage kDrawStages[] = {Stage::Vertex, Stage::Hull, Stage::Domain, Stage::Geometry, Stage::Pixel};

}  // namespace

D3d11Session::D3d11Session(int model) : model_(model) {
    HRESULT hr = D3D11CreateDevice(nullptr, D3D_DRIVER_TYPE_HARDWARE, nullptr, 0, nullptr, 0, D3D11_SDK_VERSION,
                                   device_.GetAddressOf(), nullptr, context_.GetAddressOf());
    if (FAILED(hr)) throw std::runtime_error(std::string("D3D11CreateDevice: ") + GetLastErrorMessage());
    D3D11_BUFFER_DESC d;
    d.ByteWidth = kConstantBytes;
    d.BindFlags = D3D11_BIND_CONSTANT_BUFFER;
    const std::vector<std::uint32_t> zeros(kConstantBytes / 4, 0);  // what a run without `uniform` reads
    D3D11_SUBRESOURCE_DATA data{zeros.data(), 0, 0};
    check(device_->CreateBuffer(&d, &data, constants_.GetAddressOf()), "constant buffer 0");
}

D3d11Session::~D3d11Session() {
    if (context_) context_->ClearState();
}

void D3d11Session::throwIfUnmade(const std::map<int, std::string>& unmade) const {
    if (!unmade.empty()) throw Unsupported(unmade.begin()->second);
}

const D3d11Session::Shader& D3d11Session::shaderOf(const StageSource& s, const RequireDesc& require) {
    const std::string key = std::to_string(int(s.stage)) + "\x01" + require.matrixPacking + "\x01" + s.source;
    if (auto known = shaders_.find(key); known != shaders_.end()) return known->second;
    const std::string text = preparedSource(s.source, require);
    const std::string profile = shaderProfile(s.stage, model_);
    const std::string name = "section-L" + std::to_string(s.line) + ".hlsl";
    Shader shader;
    ComPtr<ID3DBlob> errors;
    if (FAILED(D3DCompile(text.data(), text.size(), name.c_str(), nullptr, nullptr, "main", profile.c_str(), 0, 0,
                          shader.code.GetAddressOf(), errors.GetAddressOf())))
        throw std::runtime_error("D3DCompile " + profile + ": " + firstError(errors.Get()));
    const void* code = shader.code->GetBufferPointer();
    const SIZE_T size = shader.code->GetBufferSize();
    const std::string what = "Create shader (" + profile + ")";
    // Made as its own interface, held as the device child every shader interface derives from.
    auto make = [&](auto create, auto* typed) {
        ComPtr<std::remove_pointer_t<decltype(typed)>> object;
        check((device_.Get()->*create)(code, size, nullptr, object.GetAddressOf()), what);
        shader.object = ComPtr<ID3D11DeviceChild>(object.Get());
    };
    switch (s.stage) {
    case Stage::Vertex: make(&ID3D11Device::CreateVertexShader, static_cast<ID3D11VertexShader*>(nullptr)); break;
    case Stage::Pixel: make(&ID3D11Device::CreatePixelShader, static_cast<ID3D11PixelShader*>(nullptr)); break;
    case Stage::Geometry: make(&ID3D11Device::CreateGeometryShader, static_cast<ID3D11GeometryShader*>(nullptr)); break;
    case Stage::Hull: make(&ID3D11Device::CreateHullShader, static_cast<ID3D11HullShader*>(nullptr)); break;
    case Stage::Domain: make(&ID3D11Device::CreateDomainShader, static_cast<ID3D11DomainShader*>(nullptr)); break;
    case Stage::Compute: make(&ID3D11Device::CreateComputeShader, static_cast<ID3D11ComputeShader*>(nullptr)); break;
    default: throw Unsupported("stage " + std::string(stageName(s.stage)) + " in a draw");
    }
    return shaders_[key] = std::move(shader);
}

void D3d11Session::setShaders(const ShaderSet& shaders) {
    std::map<Stage, ID3D11DeviceChild*> set;
    for (const StageSource& s : shaders.stages) set[s.stage] = shaderOf(s, shaders.require).object.Get();
    auto of = [&](Stage stage) { return set.count(stage) ? set[stage] : nullptr; };
    context_->VSSetShader(static_cast<ID3D11VertexShader*>(of(Stage::Vertex)), nullptr, 0);
    context_->HSSetShader(static_cast<ID3D11HullShader*>(of(Stage::Hull)), nullptr, 0);
    context_->DSSetShader(static_cast<ID3D11DomainShader*>(of(Stage::Domain)), nullptr, 0);
    context_->GSSetShader(static_cast<ID3D11GeometryShader*>(of(Stage::Geometry)), nullptr, 0);
    context_->PSSetShader(static_cast<ID3D11PixelShader*>(of(Stage::Pixel)), nullptr, 0);
    context_->CSSetShader(static_cast<ID3D11ComputeShader*>(of(Stage::Compute)), nullptr, 0);
}

// The uniform words at the start of constant buffer 0, zeros after them.
void D3d11Session::setUniforms(const std::vector<std::uint32_t>& uniforms) {
    if (uniforms.size() * 4 > kConstantBytes) throw Unsupported("uniforms beyond D3D11's 4096 constant registers");
    if (uniforms == constantWords_) return;
    std::vector<std::uint32_t> words(kConstantBytes / 4, 0);
    std::copy(uniforms.begin(), uniforms.end(), words.begin());
    context_->UpdateSubresource(constants_.Get(), 0, nullptr, words.data(), 0, 0);
    checkNoMessage("UpdateSubresource of constant buffer 0");
    constantWords_ = uniforms;
}

void D3d11Session::bindStageResources(Stage stage) {
    const StageCalls calls = callsOf(stage);
    ID3D11Buffer* constants = constants_.Get();
    ID3D11DeviceContext& c = *context_.Get();
    (c.*calls.constants)(0, 1, &constants);
    std::vector<ID3D11ShaderResourceView*> views = bySlot(srvs_);
    if (!views.empty()) (c.*calls.views)(0, UINT(views.size()), views.data());
    std::vector<ID3D11SamplerState*> samplers = bySlot(samplers_);
    if (!samplers.empty()) (c.*calls.samplers)(0, UINT(samplers.size()), samplers.data());
}

void D3d11Session::bindTargets() {
    ensureDefaultTarget();
    throwIfUnmade(unmadeTargets_);
    std::vector<ID3D11RenderTargetView*> views;
    for (const auto& [slot, target] : targets_) {
        if (slot != int(views.size())) throw Unsupported("render targets not numbered from 0 without gaps");
        views.push_back(target.rtv.Get());
    }
    // The pixel shader's UAVs share the output slots: u# after the targets. A [uav N] under a
    // target's slot cannot be bound (a shader that uses it fails its draw, naming the u#).
    std::vector<ID3D11UnorderedAccessView*> uavs(D3D11_PS_CS_UAV_REGISTER_COUNT - views.size(), nullptr);
    for (const auto& [slot, uav] : uavs_) {
        if (slot >= int(D3D11_PS_CS_UAV_REGISTER_COUNT)) throw Unsupported("[uav " + std::to_string(slot) + "] (D3D11 has u0..u7)");
        if (slot >= int(views.size())) uavs[std::size_t(slot) - views.size()] = uav.view.Get();
    }
    context_->OMSetRenderTargetsAndUnorderedAccessViews(UINT(views.size()), views.data(), nullptr, UINT(views.size()), UINT(uavs.size()), uavs.data(), nullptr);
    D3D11_VIEWPORT viewport;
    viewport.Width = float(targets_.at(0).desc.width);
    viewport.Height = float(targets_.at(0).desc.height);
    context_->RSSetViewports(1, &viewport);
}

// The input layout and vertex buffers of a draw: the [input layout] over the [vb N] buffers, or
// vkd3d's "draw quad" (float2 positions of one triangle that covers the target).
void D3d11Session::setInputs(const ShaderSet& shaders, const DrawCall& call) {
    std::vector<InputElement> quad = {InputElement{0, Format{"r32g32-float", 2, 'f', false}, "POSITION", 0}};
    const std::vector<InputElement>& layout = call.quad ? quad : layout_;
    InputElements inputs = inputElementsOf(layout);
    ComPtr<ID3D11InputLayout> inputLayout;
    if (!inputs.elements.empty()) {
        const StageSource* vs = nullptr;
        for (const StageSource& s : shaders.stages)
            if (s.stage == Stage::Vertex) vs = &s;
        if (!vs) throw Unsupported("an input layout without a vertex shader");
        ID3DBlob* code = shaderOf(*vs, shaders.require).code.Get();
        check(device_->CreateInputLayout(inputs.elements.data(), UINT(inputs.elements.size()), code->GetBufferPointer(), code->GetBufferSize(),
                                         inputLayout.GetAddressOf()),
              "");
    }
    context_->IASetInputLayout(inputLayout.Get());
    for (const auto& [slot, stride] : inputs.strides) {
        std::vector<std::uint32_t> words;
        if (call.quad) {
            const float corners[6] = {-2.0f, -2.0f, -2.0f, 4.0f, 4.0f, -2.0f};
            words.resize(6);
            std::memcpy(words.data(), corners, sizeof corners);
        } else if (auto vb = vertexBuffers_.find(slot); vb != vertexBuffers_.end()) {
            words = vb->second.data;
        }
        // D3D reads 0 past a buffer's end; the device core wants every vertex there.
        words.resize(std::max(words.size(), std::size_t(stride) * std::size_t(call.vertexCount * call.instances) / 4 + 4), 0);
        D3D11_BUFFER_DESC d;
        d.ByteWidth = UINT(words.size() * 4);
        d.BindFlags = D3D11_BIND_VERTEX_BUFFER;
        D3D11_SUBRESOURCE_DATA data{words.data(), 0, 0};
        ComPtr<ID3D11Buffer> buffer;
        check(device_->CreateBuffer(&d, &data, buffer.GetAddressOf()), "vertex buffer " + std::to_string(slot));
        const UINT offset = 0;
        ID3D11Buffer* b = buffer.Get();
        context_->IASetVertexBuffers(UINT(slot), 1, &b, &stride, &offset);
    }
    context_->IASetPrimitiveTopology(topologyOf(call));
}

std::string D3d11Session::draw(const ShaderSet& shaders, const std::vector<std::uint32_t>& uniforms, const DrawCall& call) {
    if (!fixedFunction_.empty())
        throw Unsupported("test state '" + fixedFunction_ + "' (D3D11 has no D3D9 fixed-function states)");
    throwIfUnmade(unmadeSrvs_);
    throwIfUnmade(unmadeSamplers_);
    bindTargets();
    setShaders(shaders);
    setUniforms(uniforms);
    for (Stage stage : kDrawStages) bindStageResources(stage);
    setInputs(shaders, call);
    // D3D's defaults but culling: vkd3d's runner draws both faces.
    D3D11_RASTERIZER_DESC r;
    r.CullMode = D3D11_CULL_NONE;
    ComPtr<ID3D11RasterizerState> rasterizer;
    check(device_->CreateRasterizerState(&r, rasterizer.GetAddressOf()), "");
    context_->RSSetState(rasterizer.Get());
    context_->OMSetBlendState(nullptr, nullptr, sampleMask_);
    if (call.instances != 1) context_->DrawInstanced(UINT(call.vertexCount), UINT(call.instances), 0, 0);
    else context_->Draw(UINT(call.vertexCount), 0);
    checkNoMessage("Draw");
    forgetReadbacks();
    return {};
}

std::string D3d11Session::dispatch(const ShaderSet& shaders, const std::vector<std::uint32_t>& uniforms, int x, int y, int z) {
    throwIfUnmade(unmadeSrvs_);
    throwIfUnmade(unmadeSamplers_);
    throwIfUnmade(unmadeUavs_);
    setShaders(shaders);
    setUniforms(uniforms);
    bindStageResources(Stage::Compute);
    std::vector<ID3D11UnorderedAccessView*> views(D3D11_PS_CS_UAV_REGISTER_COUNT, nullptr);
    for (const auto& [slot, uav] : uavs_) {
        if (slot < 0 || slot >= int(views.size())) throw Unsupported("UAV slot " + std::to_string(slot) + " (D3D11 has u0..u7)");
        views[std::size_t(slot)] = uav.view.Get();
    }
    context_->CSSetUnorderedAccessViews(0, UINT(views.size()), views.data(), nullptr);
    context_->Dispatch(UINT(x), UINT(y), UINT(z));
    checkNoMessage("Dispatch");
    forgetReadbacks();
    return {};
}

void D3d11Session::clearTarget(int slot, const float rgba[4]) {
    ensureDefaultTarget();
    auto it = targets_.find(slot);
    if (it == targets_.end()) {
        auto bad = unmadeTargets_.find(slot);
        throw Unsupported(bad != unmadeTargets_.end() ? bad->second : "clear of an undeclared render target");
    }
    context_->ClearRenderTargetView(it->second.rtv.Get(), rgba);
    it->second.readback.clear();
}

}  // namespace conformance
